#include "modes/passive_modes.hpp"

#include <algorithm>
#include <cmath>

#include "core/robot_model.hpp"
#include "safety/damping_command.hpp"
#include "control/joint_ramp.hpp"

namespace cerebellum {

const char* OffMode::check(const HighLevelCommand& command) const {
  return command.gait_id == 0 ? nullptr : "mode 0 has only gait 0";
}

void OffMode::run(const RobotState& state, JointCommand& command) {
  command = JointCommand{};
  command.q_des = state.q;
}

PureDamperConfig default_pure_damper_config() {
  PureDamperConfig config;
  config.lying_pose = robot::kLyingPose;
  return config;
}

PureDamperMode::PureDamperMode(const PureDamperConfig& config) : config_(config) {}

const char* PureDamperMode::check(const HighLevelCommand& command) const {
  if (command.gait_id != 0 && command.gait_id != 1) return "mode 7 accepts gait 0 (passive) or 1 (active lie-down)";
  return nullptr;
}

void PureDamperMode::enter(const RobotState& state, const HighLevelCommand& command) {
  gait_ = command.gait_id;
  started_ = false;
  elapsed_s_ = 0.0;
  start_q_ = state.q;
}

void PureDamperMode::update(const RobotState& state, const HighLevelCommand& command) {
  if (command.gait_id != gait_) enter(state, command);
}

void PureDamperMode::run(const RobotState& state, JointCommand& command) {
  if (!started_) {
    started_ = true;
    start_time_s_ = state.time_s;
    start_q_ = state.q;
  }
  elapsed_s_ = state.time_s - start_time_s_;
  command = JointCommand{};
  if (gait_ == 0) {
    command = damping_command(config_.damping_kd, state.q);
    return;
  }
  const double s = smooth_step(elapsed_s_ / config_.lie_down_duration_s);
  ramp_joints(start_q_, on_every_leg(config_.lying_pose), s, config_.lie_down_kp, config_.lie_down_kd, command);
}

int PureDamperMode::progress_percent() const {
  if (gait_ == 0) return 100;
  return static_cast<int>(std::clamp(elapsed_s_ / config_.lie_down_duration_s, 0.0, 1.0) * 100.0);
}

}  // namespace cerebellum
