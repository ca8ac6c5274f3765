// The configuration's `locomotion_limits:` section: mode 11's velocity clamps per stepping gait and
// its swing-height clamp, beyond the product's (config/extended.yaml, config/extended-terrain.yaml).
// Absent, the product's stay.
#pragma once

#include <yaml-cpp/yaml.h>

#include <string>

#include "modes/command_ranges.hpp"

namespace cerebellum {

// locomotion_limits: over the product's limits in `limits`; throws ConfigError naming the key and
// the file. Keys: step_height_max_m, and gait_<id> for each stepping gait of the table with
// forward_max_m_s, backward_max_m_s, lateral_max_m_s, yaw_rate_max_rad_s (each optional: the
// product's value where absent)
void read_locomotion_limits_section(const YAML::Node& node, const std::string& path, LocomotionLimits& limits);

}  // namespace cerebellum
