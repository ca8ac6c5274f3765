// The decide + control stage of the cycle: robot state in, joint command out.
#pragma once

#include "core/robot_state.hpp"
#include "core/types.hpp"

namespace cerebellum {

class MotionController {
 public:
  virtual ~MotionController() = default;
  // called every tick, in the loop thread; must not block, allocate or print
  virtual void compute(const RobotState& state, JointCommand& command) = 0;
};

}  // namespace cerebellum
