// The configuration's `robot:` section: which robot (kind) and its settings (the simulation's
// model and start, or the motor SDK link), and what a real robot cannot have (the simulation's
// truth and control channel, a served interface on the robot's own link), refused by key.
#pragma once

#include <yaml-cpp/yaml.h>

#include <string>

#include "loop/mc_config.hpp"

namespace cerebellum {

// robot: into config; relative paths relative to base_dir; throws ConfigError naming the key and the file
void read_robot_section(const YAML::Node& node, const std::string& path, const std::string& base_dir,
                        McConfig& config);
// after every section was read: on a robot that is not simulated, sim_truth and sim_command are
// off (refused when the file turns them on) and no served url may share the robot's link
void check_robot_fits(const YAML::Node& root, const std::string& path, McConfig& config);

}  // namespace cerebellum
