#include "loop/robot_section.hpp"

#include <filesystem>
#include <iterator>
#include <set>
#include <stdexcept>
#include <utility>
#include <vector>

#include "io/lcm_highlevel/lcm_highlevel_config.hpp"
#include "io/shm_lowlevel/shm_lowlevel_config.hpp"
#include "loop/yaml_section.hpp"

namespace cerebellum {
namespace {

namespace fs = std::filesystem;

constexpr const char* kMotorSdkSection = "cyberdog2_motor_sdk";
constexpr const char* kShmSection = "zsibot_shm";
// the simulation's own keys: a real robot has no model to load nor a pose to start in
const std::set<std::string> kSimulationKeys{"initial_pose", "initial_height_m", "sensor_noise", "seed", "terrain",
                                            "command_latency_ticks", "state_latency_ticks"};
// 50 ms at the default 2 ms tick: far beyond a real link's watch (robot.*.link_timeout_s, 20 ms
// by default), past which a robot is damped as lost
constexpr unsigned kLatencyTicksMax = 25;

void read_latency(const SectionReader& section, const char* key, int& ticks) {
  unsigned value = static_cast<unsigned>(ticks);
  section.unsigned_integer(key, value);
  if (value > kLatencyTicksMax) {
    section.fail(std::string("robot.") + key,
                 "must be at most " + std::to_string(kLatencyTicksMax) + " ticks, got " + std::to_string(value));
  }
  ticks = static_cast<int>(value);
}

void read_simulation(const SectionReader& section, const std::string& base_dir, MujocoBackendConfig& robot,
                     LinkLatencyTicks& latency) {
  if (section.has("terrain")) {
    std::string terrain;
    section.text("terrain", terrain);
    try {
      robot.terrain = parse_terrain_spec(terrain);
    } catch (const std::invalid_argument& e) {
      section.fail("robot.terrain", e.what());
    }
    // a terrain file is found beside the configuration, as the model is
    if (robot.terrain.kind == TerrainKind::File && fs::path(robot.terrain.file).is_relative()) {
      robot.terrain.file = (fs::path(base_dir) / robot.terrain.file).lexically_normal().string();
    }
  }
  section.text("initial_pose", robot.initial_keyframe, {"lying", "stand"});
  section.number("initial_height_m", robot.initial_height_m, 0.05, 2.0);
  section.flag("sensor_noise", robot.noise.enabled);
  section.unsigned_integer("seed", robot.noise.seed);
  read_latency(section, "command_latency_ticks", latency.command_ticks);
  read_latency(section, "state_latency_ticks", latency.state_ticks);
}

void read_motor_sdk_robot(const YAML::Node& node, const std::string& path, MotorSdkRobotConfig& robot) {
  const std::string name = std::string("robot.") + kMotorSdkSection;
  const SectionReader section(node, path, name,
                              {"control_url", "estimator_url", "link_timeout_s", "activation_timeout_s",
                               "motor_error_damping_kd", "position_jump_limit"});
  for (const auto& [key, url] : {std::pair<const char*, std::string*>{"control_url", &robot.control_url},
                                 std::pair<const char*, std::string*>{"estimator_url", &robot.estimator_url}}) {
    section.text(key, *url);
    if (const std::string problem = lcm_url_problem(*url); !problem.empty()) {
      section.fail(name + "." + key, problem + ", got '" + *url + "'");
    }
  }
  // below 4 ms two of the robot's 2 ms frames may be missed in a healthy link; above 0.5 s the
  // robot's own err_flag bit 1 has already laid it down
  section.number("link_timeout_s", robot.link_timeout_s, 0.004, 0.5);
  section.number("activation_timeout_s", robot.activation_timeout_s, 1.0, 120.0);
  section.number("motor_error_damping_kd", robot.motor_error_damping_kd, 0.5, robot::kCommandKdMax);
  section.flag("position_jump_limit", robot.rules.position_mutation_limit);
}

void read_shm_robot(const YAML::Node& node, const std::string& path, ShmRobotConfig& robot) {
  const std::string name = std::string("robot.") + kShmSection;
  const SectionReader section(node, path, name,
                              {"name_prefix", "link_timeout_s", "activation_timeout_s", "motor_error_damping_kd"});
  section.text("name_prefix", robot.name_prefix);
  if (const std::string problem = shm_name_prefix_problem(robot.name_prefix); !problem.empty()) {
    section.fail(name + ".name_prefix", problem + ", got '" + robot.name_prefix + "'");
  }
  // below 3 ms two of the daemon's 1 ms updates may be missed in a healthy link; above 0.5 s the
  // legs would hang on a dead daemon far too long (the vendor's own rule lies the robot down after 3 s)
  section.number("link_timeout_s", robot.link_timeout_s, 0.003, 0.5);
  section.number("activation_timeout_s", robot.activation_timeout_s, 1.0, 120.0);
  section.number("motor_error_damping_kd", robot.motor_error_damping_kd, 0.5, robot::kCommandKdMax);
}

// "239.255.76.67:7667" of "udpm://239.255.76.67:7667?ttl=0": where packets meet, whatever the ttl
std::string lcm_endpoint(const std::string& url) {
  const std::size_t start = url.find("://");
  const std::size_t from = start == std::string::npos ? 0 : start + 3;
  return url.substr(from, url.find('?', from) - from);
}

}  // namespace

void read_robot_section(const YAML::Node& node, const std::string& path, const std::string& base_dir,
                        McConfig& config) {
  // every kind's keys, then the simulation's (refused below on a real robot, by name)
  std::set<std::string> accepted{"kind", "model", kMotorSdkSection, kShmSection};
  accepted.insert(kSimulationKeys.begin(), kSimulationKeys.end());
  const SectionReader section(node, path, "robot", accepted);
  std::string kind = robot_kind_name(config.robot_kind);
  section.text("kind", kind, std::set<std::string>(std::begin(kRobotKindNames), std::end(kRobotKindNames)));
  for (int k = 0; k < static_cast<int>(std::size(kRobotKindNames)); ++k) {
    if (kind == kRobotKindNames[k]) config.robot_kind = static_cast<RobotKind>(k);
  }
  // the model serves every kind: the two-leg stand designs its balance on it
  std::string model;
  section.path("model", model);
  if (!model.empty()) {
    const fs::path model_path(model);
    config.robot.model_path =
        (model_path.is_absolute() ? model_path : fs::path(base_dir) / model_path).lexically_normal().string();
  }
  // each robot's own subsection only with its kind
  for (const auto& [subsection, owner] : {std::pair{kMotorSdkSection, RobotKind::Cyberdog2MotorSdk},
                                          std::pair{kShmSection, RobotKind::ZsibotShm}}) {
    if (section.has(subsection) && config.robot_kind != owner) {
      section.fail(std::string("robot.") + subsection, std::string("applies only to robot.kind ") +
                                                           robot_kind_name(owner) + " (robot.kind is " + kind + ")");
    }
  }
  if (config.robot_kind == RobotKind::Sim) {
    read_simulation(section, base_dir, config.robot, config.simulated_link_latency);
    return;
  }
  for (const std::string& key : kSimulationKeys) {
    if (section.has(key)) {
      section.fail("robot." + key, std::string("applies only to the simulated robot (robot.kind is ") + kind + ")");
    }
  }
  if (section.has(kMotorSdkSection)) read_motor_sdk_robot(node[kMotorSdkSection], path, config.motor_sdk_robot);
  if (section.has(kShmSection)) read_shm_robot(node[kShmSection], path, config.shm_robot);
}

void check_robot_fits(const YAML::Node& root, const std::string& path, McConfig& config) {
  if (config.robot_kind == RobotKind::Sim) return;
  const std::string kind = robot_kind_name(config.robot_kind);
  const auto refuse = [&](const std::string& key, const std::string& what) {
    throw ConfigError("config " + path + ": " + key + " " + what);
  };
  // the simulation's tools have nothing to act on: off unless the file asks, and then refused
  if (root["sim_truth"] && root["sim_truth"]["rate_hz"] && config.sim_truth.rate_hz > 0.0) {
    refuse("sim_truth.rate_hz", "must be 0 on a real robot: there is no simulator truth (robot.kind is " + kind + ")");
  }
  config.sim_truth.rate_hz = 0.0;
  if (root["sim_command"] && root["sim_command"]["enabled"] && config.sim_command.enabled) {
    refuse("sim_command.enabled",
           "must be false on a real robot: push and fault act only on a simulation (robot.kind is " + kind + ")");
  }
  config.sim_command.enabled = false;
  // the shared memory this MC would serve is the daemon's it reads, when both have one name
  if (config.robot_kind == RobotKind::ZsibotShm) {
    if (config.shm.enabled && config.shm.name_prefix == config.shm_robot.name_prefix) {
      refuse("shm.enabled", "would serve " + shm_spline_object_name(config.shm.name_prefix) +
                                ", the robot's own daemon's object (robot." + kShmSection +
                                ".name_prefix): turn shm off or give it another name_prefix");
    }
    return;
  }
  // a served interface on the robot's own link would read its own frames as the robot's (or the
  // robot would read ours): each served url needs another port than the robot's two
  const MotorSdkRobotConfig& link = config.motor_sdk_robot;
  const std::vector<std::pair<std::string, std::string>> served{
      {"motor_sdk.control_url", config.motor_sdk.control_url},
      {"motor_sdk.estimator_url", config.motor_sdk.estimator_url},
      {"highlevel.command_url", config.highlevel.command_url},
      {"highlevel.response_url", config.highlevel.response_url},
      {"highlevel.odometry_url", config.highlevel.odometry_url}};
  const bool state_feedback = config.motor_sdk.enabled || config.highlevel.enabled;
  for (const auto& [key, url] : served) {
    const bool in_use = key.rfind("motor_sdk.", 0) == 0 ? state_feedback : config.highlevel.enabled;
    if (!in_use) continue;
    for (const auto& [robot_key, robot_url] :
         {std::pair<const char*, const std::string&>{"control_url", link.control_url},
          std::pair<const char*, const std::string&>{"estimator_url", link.estimator_url}}) {
      if (lcm_endpoint(url) != lcm_endpoint(robot_url)) continue;
      refuse(key, "'" + url + "' is the robot's own link (robot." + kMotorSdkSection + "." + robot_key +
                      "): give the served interface another port");
    }
  }
}

}  // namespace cerebellum
