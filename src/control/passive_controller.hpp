// The robot's resting behaviours: Off (motors passive) and PureDamper (joint damping, the robot
// sinks and lies down by itself).
#pragma once

#include "control/motion_controller.hpp"

namespace cerebellum {

class PassiveController final : public MotionController {
 public:
  // damping_kd 0: Off; > 0: PureDamper
  explicit PassiveController(double damping_kd) : damping_kd_(damping_kd) {}
  void compute(const RobotState& state, JointCommand& command) override;

 private:
  double damping_kd_;
};

}  // namespace cerebellum
