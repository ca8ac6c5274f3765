// The MC's configuration: one YAML file, every key documented in docs/configuration.md and
// validated on load (unknown keys, wrong types and out-of-range values are errors).
#pragma once

#include <stdexcept>
#include <string>

#include "loop/config_error.hpp"
#include "loop/realtime_config.hpp"
#include "loop/robot_kind.hpp"
#include "backend/latent_link_backend.hpp"
#include "backend/mujoco_backend.hpp"
#include "control/locomotion/locomotion_controller.hpp"
#include "control/stand_up_controller.hpp"
#include "io/lcm_highlevel/lcm_highlevel_config.hpp"
#include "io/lcm_motor_sdk/lcm_motor_sdk_config.hpp"
#include "io/lcm_motor_sdk_robot/motor_sdk_robot_config.hpp"
#include "io/shm_lowlevel_robot/shm_robot_config.hpp"
#include "io/lcm_sim_control/sim_control_config.hpp"
#include "io/lcm_sim_truth/sim_truth_config.hpp"
#include "io/shm_lowlevel/shm_lowlevel_config.hpp"
#include "io/udp_aliengo/udp_aliengo_config.hpp"
#include "modes/aliengo_session.hpp"
#include "modes/command_ranges.hpp"
#include "modes/locomotion_stand.hpp"
#include "motions/motion_folder.hpp"
#include "safety/command_guard.hpp"

namespace cerebellum {

// what the MC does by itself after start
enum class Startup {
  Stand,   // stand up and hold
  Off,     // motors passive, as the robot after power-on: it lies and takes a high-level client or
           // a low-level one (the motor SDK and the shared memory take over only from Off or PureDamper)
  Damper,  // joint damping (PureDamper); low-level clients may take over
};
const char* startup_name(Startup startup);  // as the configuration writes it
// what the robot does at start and who may take it, for the start-up log line
const char* startup_meaning(Startup startup);

struct McConfig {
  // as the robot powers on: lying, motors off, whichever client comes first may take it
  Startup startup = Startup::Off;
  LocomotionStand locomotion_stand = LocomotionStand::Mpc;
  RobotKind robot_kind = RobotKind::Sim;  // robot.kind
  MujocoBackendConfig robot;               // the simulation (and the model every kind reads)
  LinkLatencyTicks simulated_link_latency; // robot.command_latency_ticks, robot.state_latency_ticks
  MotorSdkRobotConfig motor_sdk_robot;     // robot.cyberdog2_motor_sdk: the CyberDog2's motor SDK link
  ShmRobotConfig shm_robot;                // robot.zsibot_shm: the ZsiBot daemon's shared memory
  double loop_period_s = 0.002;
  RealtimeConfig realtime;  // the process's scheduling, memory locking and CPUs
  StandUpConfig stand_up = default_stand_up_config();
  GuardLimits safety;
  ShmLowLevelConfig shm;
  MotorSdkConfig motor_sdk;
  HighLevelLcmConfig highlevel;
  AlienGoUdpConfig aliengo;              // the transport (section aliengo:)
  AlienGoSessionConfig aliengo_session;  // the sport session's timers (section aliengo: too)
  MotionFolders motions;                 // mode 62's motion files
  // the flips' plans (docs/jumps.md), beside the model's folder: models/../config/flips in the
  // source tree and share/cerebellum/config/flips installed; empty: that flip (16/20 back, 16/21
  // front) is refused
  std::string back_flip_path;
  std::string front_flip_path;
  // mode 11's clamps (section locomotion_limits:): the product's by default; config/extended.yaml
  // and config/extended-terrain.yaml go beyond them (docs/locomotion.md, "Beyond the product")
  LocomotionLimits locomotion_limits;
  // the walking controller's settings (section locomotion: sets those the product's tuning leaves
  // off: velocity_trim_gain_per_s, early_touchdown_force_n, foothold_on_own_ground,
  // late_touchdown_reach_m; its tick follows loop_period_s)
  LocomotionConfig locomotion;
  SimTruthConfig sim_truth;              // simulation only
  SimControlConfig sim_command;          // simulation only
};

// defaults, with the model found next to the build or install tree
McConfig default_config();
// defaults overridden by the file's keys; relative paths are taken relative to the file
McConfig load_config(const std::string& path);

}  // namespace cerebellum
