#include "control/stand_up_controller.hpp"

#include <algorithm>
#include <cmath>

#include "core/robot_model.hpp"
#include "control/joint_ramp.hpp"

namespace cerebellum {

StandUpConfig default_stand_up_config() {
  StandUpConfig config;
  config.lying_pose = robot::kLyingPose;
  config.stand_pose = robot::kStandPose;
  return config;
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
  const JointArray<double> lying = on_every_leg(config_.lying_pose);
  ramp_joints(folding ? start_q_ : lying, folding ? lying : on_every_leg(config_.stand_pose), fraction, config_.kp,
              config_.kd, command);
}

}  // namespace cerebellum
