#include "control/stand_up_controller.hpp"

#include <algorithm>
#include <cmath>

#include "core/robot_model.hpp"

namespace cerebellum {

StandUpConfig default_stand_up_config() {
  StandUpConfig config;
  config.lying_pose = robot::kLyingPose;
  config.stand_pose = robot::kStandPose;
  return config;
}

double smooth_step(double fraction) {
  const double s = std::clamp(fraction, 0.0, 1.0);
  return 0.5 - 0.5 * std::cos(robot::kPi * s);
}

StandUpController::StandUpController(const StandUpConfig& config) : config_(config) {}

void StandUpController::compute(const RobotState& state, JointCommand& command) {
  if (!started_) {
    started_ = true;
    start_time_s_ = state.time_s;
    start_q_ = state.q;
  }
  const double elapsed = state.time_s - start_time_s_;
  const double total = config_.fold_duration_s + config_.rise_duration_s;
  progress_ = total > 0.0 ? std::clamp(elapsed / total, 0.0, 1.0) : 1.0;

  // first segment: start -> lying; second: lying -> stand
  const bool folding = elapsed < config_.fold_duration_s;
  const double fraction = folding ? smooth_step(elapsed / config_.fold_duration_s)
                                  : smooth_step((elapsed - config_.fold_duration_s) / config_.rise_duration_s);
  for (std::size_t i = 0; i < kNumJoints; ++i) {
    const double lying = config_.lying_pose[i % kJointsPerLeg];
    const double from = folding ? start_q_[i] : lying;
    const double to = folding ? lying : config_.stand_pose[i % kJointsPerLeg];
    command.q_des[i] = from + (to - from) * fraction;
    command.qd_des[i] = 0.0;
    command.kp[i] = config_.kp;
    command.kd[i] = config_.kd;
    command.tau_ff[i] = 0.0;
  }
}

}  // namespace cerebellum
