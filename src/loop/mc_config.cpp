#include "loop/mc_config.hpp"

#include <yaml-cpp/yaml.h>

#include <cmath>
#include <filesystem>
#include <set>
#include <sstream>

#include "loop/locomotion_limits_section.hpp"
#include "loop/robot_section.hpp"
#include "loop/yaml_section.hpp"
#include "core/robot_model.hpp"
#include "io/lcm_common/lcm_network.hpp"
#include "lowlevel/motor_sdk/motor_sdk_user_parameters.hpp"

namespace cerebellum {
namespace {

namespace fs = std::filesystem;

std::string find_default_model() {
  for (const char* dir : {CEREBELLUM_SOURCE_MODEL_DIR, CEREBELLUM_INSTALL_MODEL_DIR}) {
    const fs::path candidate = fs::path(dir) / "cyberdog2.xml";
    if (fs::is_regular_file(candidate)) return candidate.string();
  }
  return (fs::path(CEREBELLUM_INSTALL_MODEL_DIR) / "cyberdog2.xml").string();
}

std::string find_default_motions() {
  for (const char* dir : {CEREBELLUM_SOURCE_MOTION_DIR, CEREBELLUM_INSTALL_MOTION_DIR}) {
    if (fs::is_directory(dir)) return dir;
  }
  return CEREBELLUM_INSTALL_MOTION_DIR;
}

// a flip's plan in config/flips beside the model's folder, or "" when there is none
std::string find_default_flip(const char* file_name) {
  for (const char* dir : {CEREBELLUM_SOURCE_MODEL_DIR, CEREBELLUM_INSTALL_MODEL_DIR}) {
    const fs::path candidate = fs::path(dir) / ".." / "config" / "flips" / file_name;
    if (fs::is_regular_file(candidate)) return candidate.lexically_normal().string();
  }
  return "";
}

void read_motions(const SectionReader& section, const fs::path& base_dir, MotionFolders& motions) {
  for (const auto& [key, folder] : {std::pair<const char*, std::string*>{"folder", &motions.folder},
                                    std::pair<const char*, std::string*>{"user_folder", &motions.user_folder}}) {
    std::string given;
    section.text(key, given);
    if (given.empty()) continue;
    const fs::path path(given);
    *folder = (path.is_absolute() ? path : base_dir / path).lexically_normal().string();
    if (!fs::is_directory(*folder)) section.fail(std::string("motions.") + key, "is not a folder: " + *folder);
  }
}

void read_shm(const SectionReader& section, ShmLowLevelConfig& shm) {
  section.flag("enabled", shm.enabled);
  section.text("name_prefix", shm.name_prefix);
  const std::string prefix_problem = shm_name_prefix_problem(shm.name_prefix);
  if (!prefix_problem.empty()) section.fail("shm.name_prefix", prefix_problem);
  std::string group;
  section.text("group", group);
  if (!group.empty()) {
    shm.group_id = find_group_id(group);
    if (!shm.group_id) section.fail("shm.group", "is not a group of this system: '" + group + "'");
  }
  std::string mode;
  section.text("mode", mode);
  if (mode.empty()) return;
  const std::optional<unsigned> parsed = parse_shm_mode(mode);
  if (!parsed) {
    section.fail(
        "shm.mode",
        "must be octal permission bits (0600 .. 0777, with owner read and write, e.g. 0660), got '" + mode + "'");
  }
  shm.mode = *parsed;
}

void read_motor_sdk(const SectionReader& section, const fs::path& base_dir, MotorSdkConfig& motor_sdk) {
  section.flag("enabled", motor_sdk.enabled);
  const auto read_url = [&section](const std::string& key, std::string& url) {
    section.text(key, url);
    if (url.find("://") == std::string::npos) {
      section.fail("motor_sdk." + key,
                   "must be an LCM url such as " + lcm_url(kLcmMotorSdkPort, 255) + ", got '" + url + "'");
    }
  };
  read_url("control_url", motor_sdk.control_url);
  read_url("estimator_url", motor_sdk.estimator_url);
  std::string file;
  section.text("user_parameter_file", file);
  if (file.empty()) return;
  const fs::path file_path(file);
  motor_sdk.user_parameter_file =
      (file_path.is_absolute() ? file_path : base_dir / file_path).lexically_normal().string();
  try {
    motor_sdk.parameters.position_mutation_limit =
        load_motor_sdk_user_parameters(motor_sdk.user_parameter_file).position_mutation_limit;
  } catch (const UserParameterError& e) {
    section.fail("motor_sdk.user_parameter_file", std::string("cannot be used: ") + e.what());
  }
}

void read_highlevel(const SectionReader& section, HighLevelLcmConfig& highlevel) {
  section.flag("enabled", highlevel.enabled);
  const auto read_url = [&section](const std::string& key, std::string& url) {
    section.text(key, url);
    if (const std::string problem = lcm_url_problem(url); !problem.empty()) {
      section.fail("highlevel." + key, problem + ", got '" + url + "'");
    }
  };
  read_url("command_url", highlevel.command_url);
  read_url("response_url", highlevel.response_url);
  read_url("odometry_url", highlevel.odometry_url);
  section.number("response_keepalive_s", highlevel.response_keepalive_s, 0.0, 0.19);
}

}  // namespace

const char* startup_name(Startup startup) {
  switch (startup) {
    case Startup::Stand: return "stand";
    case Startup::Off: return "off";
    case Startup::Damper: return "damper";
  }
  return "stand";
}

const char* startup_meaning(Startup startup) {
  switch (startup) {
    case Startup::Off:
      return "the robot lies with the motors off (mode 0), as after power-on; the first client takes it: a "
             "high-level one (mode 12 stands it up) or a low-level one (motor SDK, shared memory), and the other is "
             "refused";
    case Startup::Damper:
      return "the joints are damped (mode 7); a high-level client or a low-level one (motor SDK, shared memory) may "
             "take the robot";
    case Startup::Stand:
      return "the MC stands the robot up by itself (mode 12); low-level clients are refused (they take over only "
             "from mode 0 or 7)";
  }
  return "";
}

McConfig default_config() {
  McConfig config;
  config.robot.model_path = find_default_model();
  config.motions.folder = find_default_motions();
  config.back_flip_path = find_default_flip("back_flip.csv");
  config.front_flip_path = find_default_flip("front_flip.csv");
  return config;
}

McConfig load_config(const std::string& path) {
  if (fs::is_directory(path)) throw ConfigError("config " + path + ": is a folder; give the YAML file in it");
  if (!fs::is_regular_file(path)) throw ConfigError("config file not found: " + path);
  YAML::Node root;
  try {
    root = YAML::LoadFile(path);
  } catch (const YAML::Exception& e) {
    throw ConfigError("config " + path + ": not valid YAML: " + e.what());
  }
  McConfig config = default_config();
  if (root.IsNull()) return config;
  const SectionReader top(root, path, "<top>",
                          {"mc", "robot", "loop", "realtime", "stand_up", "safety", "shm", "motor_sdk", "highlevel", "aliengo",
                           "motions", "sim_truth", "sim_command", "locomotion", "locomotion_limits"});
  const fs::path base_dir = fs::absolute(path).parent_path();

  if (root["mc"]) {
    std::string startup = startup_name(config.startup);
    std::string stand = config.locomotion_stand == LocomotionStand::Qp ? "qp" : "mpc";
    const SectionReader mc(root["mc"], path, "mc", {"startup", "locomotion_stand"});
    mc.text("startup", startup, {"stand", "off", "damper"});
    mc.text("locomotion_stand", stand, {"mpc", "qp"});
    config.startup = startup == "off" ? Startup::Off : startup == "damper" ? Startup::Damper : Startup::Stand;
    config.locomotion_stand = stand == "qp" ? LocomotionStand::Qp : LocomotionStand::Mpc;
  }
  if (root["robot"]) read_robot_section(root["robot"], path, base_dir.string(), config);
  if (root["loop"]) {
    SectionReader(root["loop"], path, "loop", {"period_s"}).number("period_s", config.loop_period_s, 0.001, 0.01);
  }
  if (root["realtime"]) {
    const SectionReader s(root["realtime"], path, "realtime", {"priority", "lock_memory", "cpus"});
    double priority = config.realtime.priority;
    s.number("priority", priority, 0, kRealtimePriorityMax);
    if (priority != std::floor(priority)) {
      s.fail("realtime.priority", "must be a whole number in [0, " + std::to_string(kRealtimePriorityMax) + "]");
    }
    config.realtime.priority = static_cast<int>(priority);
    s.flag("lock_memory", config.realtime.lock_memory);
    s.unsigned_list("cpus", config.realtime.cpus, kRealtimeCpuMax);
  }
  if (root["stand_up"]) {
    const SectionReader s(root["stand_up"], path, "stand_up", {"fold_duration_s", "rise_duration_s", "kp", "kd"});
    s.number("fold_duration_s", config.stand_up.fold_duration_s, 0.0, 10.0);
    s.number("rise_duration_s", config.stand_up.rise_duration_s, 0.1, 10.0);
    s.number("kp", config.stand_up.kp, 0.0, 200.0);
    s.number("kd", config.stand_up.kd, 0.0, 10.0);
  }
  if (root["safety"]) {
    const SectionReader s(
        root["safety"], path, "safety",
        {"kp_max", "kd_max", "tau_ff_max_nm", "qd_des_max_rad_s", "joint_limit_margin_rad", "damping_kd"});
    s.number("kp_max", config.safety.command.kp_max, 0.0, robot::kCommandKpMax);
    s.number("kd_max", config.safety.command.kd_max, 0.0, robot::kCommandKdMax);
    s.number("tau_ff_max_nm", config.safety.command.tau_ff_max_nm, 0.0, robot::kTorqueMaxNm);
    s.number("qd_des_max_rad_s", config.safety.command.qd_des_max_rad_s, 0.0, 30.0);
    s.number("joint_limit_margin_rad", config.safety.command.joint_limit_margin_rad, 0.0, 0.3);
    s.number("damping_kd", config.safety.damping_kd, 0.0, 10.0);
  }
  if (root["shm"]) {
    read_shm(SectionReader(root["shm"], path, "shm", {"enabled", "name_prefix", "mode", "group"}), config.shm);
  }
  if (root["motor_sdk"]) {
    read_motor_sdk(SectionReader(root["motor_sdk"], path, "motor_sdk",
                                 {"enabled", "control_url", "estimator_url", "user_parameter_file"}),
                   base_dir, config.motor_sdk);
  }
  if (root["highlevel"]) {
    read_highlevel(SectionReader(root["highlevel"], path, "highlevel",
                                 {"enabled", "command_url", "response_url", "odometry_url", "response_keepalive_s"}),
                   config.highlevel);
  }
  if (root["motions"]) {
    read_motions(SectionReader(root["motions"], path, "motions", {"folder", "user_folder"}), base_dir, config.motions);
  }
  if (root["aliengo"]) {
    const SectionReader s(root["aliengo"], path, "aliengo",
                          {"enabled", "bind_address", "port", "silence_stand_s", "stand_hold_s", "lie_down_s"});
    s.flag("enabled", config.aliengo.enabled);
    s.text("bind_address", config.aliengo.bind_address);
    double port = config.aliengo.port;
    s.number("port", port, 0, 65535);
    if (port != std::floor(port)) s.fail("aliengo.port", "must be a whole number in [0, 65535]");
    config.aliengo.port = static_cast<int>(port);
    s.number("silence_stand_s", config.aliengo_session.silence_stand_s, 0.05, 0.45);
    s.number("stand_hold_s", config.aliengo_session.stand_hold_s, 0.5, 10.0);
    s.number("lie_down_s", config.aliengo_session.lie_down_s, 1.5, 10.0);
    if (config.aliengo_session.stand_hold_s <= config.aliengo_session.silence_stand_s) {
      s.fail("aliengo.stand_hold_s", "must be longer than aliengo.silence_stand_s");
    }
  }
  if (root["sim_truth"]) {
    SectionReader(root["sim_truth"], path, "sim_truth", {"rate_hz"})
        .number("rate_hz", config.sim_truth.rate_hz, 0.0, kSimTruthRateMaxHz);
  }
  if (root["sim_command"]) {
    SectionReader(root["sim_command"], path, "sim_command", {"enabled"}).flag("enabled", config.sim_command.enabled);
  }
  if (root["locomotion"]) {
    const SectionReader s(root["locomotion"], path, "locomotion",
                          {"velocity_trim_gain_per_s", "early_touchdown_force_n", "foothold_on_own_ground",
                           "late_touchdown_reach_m", "slip_response"});
    s.number("velocity_trim_gain_per_s", config.locomotion.velocity_trim_gain_per_s, 0.0, 10.0);
    s.number("early_touchdown_force_n", config.locomotion.early_touchdown_force_n, 0.0, 200.0);
    s.flag("foothold_on_own_ground", config.locomotion.foothold_on_own_ground);
    s.number("late_touchdown_reach_m", config.locomotion.late_touchdown_reach_m, 0.0, 0.2);
    s.flag("slip_response", config.locomotion.slip_response);
  }
  if (root["locomotion_limits"]) read_locomotion_limits_section(root["locomotion_limits"], path, config.locomotion_limits);
  check_robot_fits(root, path, config);
  return config;
}

}  // namespace cerebellum
