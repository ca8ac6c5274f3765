#include "control/jump/flip_run.hpp"

#include <algorithm>
#include <cmath>

namespace cerebellum {

void FlipRun::start(const RobotState& state, const FlipTrajectory& trajectory) {
  trajectory_ = &trajectory;
  stage_ = FlipStage::Prepare;
  stage_start_s_ = start_s_ = state.time_s;
  start_q_ = state.q;
}

double FlipRun::progress(double time_s) const {
  if (stage_ == FlipStage::Idle || trajectory_ == nullptr) return 0.0;
  if (stage_ == FlipStage::Done) return 1.0;
  const double total = config_.prepare_s + flip_duration_s(*trajectory_) + config_.settle_max_s;
  return std::clamp((time_s - start_s_) / total, 0.0, 0.99);
}

void FlipRun::compute(const RobotState& state, JointCommand& command) {
  if (trajectory_ == nullptr || stage_ == FlipStage::Idle || stage_ == FlipStage::Done) return;
  double t = state.time_s - stage_start_s_;
  if (stage_ == FlipStage::Prepare && t >= config_.prepare_s) {
    stage_ = FlipStage::Play;
    stage_start_s_ = state.time_s;
    t = 0.0;
  }
  if (stage_ == FlipStage::Play && t >= flip_duration_s(*trajectory_)) {
    stage_ = FlipStage::Settle;
    stage_start_s_ = state.time_s;
    t = 0.0;
  }
  if (stage_ == FlipStage::Settle) {
    // the body's up axis against the world's: roll-pitch-yaw angles wrap while upside down
    const double up_z = (state.orientation * Eigen::Vector3d::UnitZ()).z();
    const bool upright = up_z > std::cos(config_.upright_tilt_rad) && std::abs(state.omega_body.y()) < config_.upright_rate_rad_s;
    if ((upright && t >= config_.settle_min_s) || t >= config_.settle_max_s) {
      stage_ = FlipStage::Done;
      return;
    }
  }
  switch (stage_) {
    case FlipStage::Prepare: {
      // the plan's start pose and its standing torques, reached linearly from the stand's joints
      command = flip_play_command(*trajectory_, 0.0, config_.gains);
      const double w = std::clamp(t / config_.prepare_s, 0.0, 1.0);
      for (std::size_t j = 0; j < kNumJoints; ++j) {
        command.q_des[j] = start_q_[j] + w * (command.q_des[j] - start_q_[j]);
        command.qd_des[j] = 0.0;
        command.tau_ff[j] *= w;
      }
      return;
    }
    case FlipStage::Play: command = flip_play_command(*trajectory_, t, config_.gains); return;
    case FlipStage::Settle:
      command = flip_play_command(*trajectory_, flip_duration_s(*trajectory_) + t, config_.gains);
      return;
    default: return;
  }
}

}  // namespace cerebellum
