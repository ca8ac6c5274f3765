// The estimation stage of the control cycle: sensor frame (and the control stage's contact plan
// from the tick before) in, robot state out.
#pragma once

#include "core/contact_plan.hpp"
#include "core/robot_state.hpp"
#include "core/types.hpp"

namespace cerebellum {

class StateEstimator {
 public:
  virtual ~StateEstimator() = default;
  virtual void reset() = 0;
  // fold one sensor frame into the estimate; a frame with NaN/Inf leaves state.valid false.
  // plan: the contacts the control stage planned for this tick (none: judge them from forces)
  virtual void update(const SensorFrame& frame, const ContactPlan& plan, RobotState& state) = 0;
};

}  // namespace cerebellum
