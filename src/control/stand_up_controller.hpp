// Joint-space stand-up: from wherever the legs are, fold them to the lying pose, then rise to
// the stand pose and hold it (the vendor's motor-SDK example does the same).
#pragma once

#include <array>

#include "control/motion_controller.hpp"

namespace cerebellum {

struct StandUpConfig {
  double fold_duration_s = 1.0;  // current pose -> lying pose
  double rise_duration_s = 1.5;  // lying pose -> stand pose
  double kp = 60.0;
  double kd = 2.0;
  std::array<double, 3> lying_pose;  // abad, hip, knee (SDK convention)
  std::array<double, 3> stand_pose;
};
StandUpConfig default_stand_up_config();

class StandUpController final : public MotionController {
 public:
  explicit StandUpController(const StandUpConfig& config);
  void compute(const RobotState& state, JointCommand& command) override;
  // 0 at the start, 1 once standing
  double progress() const { return progress_; }
  // start again from the current pose on the next tick
  void restart() { started_ = false; }

 private:
  StandUpConfig config_;
  bool started_ = false;
  double start_time_s_ = 0.0;
  JointArray<double> start_q_{};
  double progress_ = 0.0;
};

}  // namespace cerebellum
