// A played flip from the stand to its touchdown: the legs ramp from the stand to the plan's start
// pose, the plan plays (flip_player), then the landing pose is held while the trunk finishes its
// turn on the landed feet, until it is upright and slow or a time limit has passed. Then the jump
// controller lands it (JumpController::land); this class does not land.
#pragma once

#include "control/jump/flip_player.hpp"
#include "core/robot_state.hpp"

namespace cerebellum {

struct FlipRunConfig {
  FlipPlayGains gains;
  double prepare_s = 0.5;  // from the stand's joints to the plan's start pose
  // after the plan: upright within this tilt and turning slower than this, at least settle_min_s
  // and at most settle_max_s after the plan's end
  double upright_tilt_rad = 0.3;
  double upright_rate_rad_s = 2.0;
  double settle_min_s = 0.05;
  double settle_max_s = 0.8;
};

enum class FlipStage { Idle, Prepare, Play, Settle, Done };

class FlipRun {
 public:
  explicit FlipRun(const FlipRunConfig& config = {}) : config_(config) {}

  // starts from the robot's joints now; the trajectory must outlive the run
  void start(const RobotState& state, const FlipTrajectory& trajectory);
  void compute(const RobotState& state, JointCommand& command);

  FlipStage stage() const { return stage_; }
  // the flip's own time: the body turns over on purpose
  bool turning_over() const { return stage_ == FlipStage::Play || stage_ == FlipStage::Settle; }
  bool done() const { return stage_ == FlipStage::Done; }
  // 0..1 across prepare, play and settle (settle counted at its limit)
  double progress(double time_s) const;

 private:
  FlipRunConfig config_;
  const FlipTrajectory* trajectory_ = nullptr;
  FlipStage stage_ = FlipStage::Idle;
  double stage_start_s_ = 0.0;
  double start_s_ = 0.0;
  JointArray<double> start_q_{};
};

}  // namespace cerebellum
