#include "modes/lifted_mode.hpp"

#include "control/stand_up_controller.hpp"
#include "core/robot_model.hpp"
#include "control/joint_ramp.hpp"

namespace cerebellum {

LiftedConfig default_lifted_config() {
  LiftedConfig config;
  config.hold_pose = robot::kStandPose;
  return config;
}

LiftedMode::LiftedMode(const LiftedConfig& config) : config_(config) {}

const char* LiftedMode::check(const HighLevelCommand&) const {
  return "mode 9 is entered by the MC itself when the robot is picked up";
}

void LiftedMode::enter(const RobotState& state, const HighLevelCommand&) {
  start_q_ = state.q;
  start_time_s_ = state.time_s;
}

void LiftedMode::run(const RobotState& state, JointCommand& command) {
  const double s = smooth_step((state.time_s - start_time_s_) / config_.move_duration_s);
  ramp_joints(start_q_, on_every_leg(config_.hold_pose), s, config_.kp, config_.kd, command);
}

}  // namespace cerebellum
