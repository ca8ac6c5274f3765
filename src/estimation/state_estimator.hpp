// The estimation stage of the control cycle: sensor frame in, robot state out.
#pragma once

#include "core/robot_state.hpp"
#include "core/types.hpp"

namespace cerebellum {

class StateEstimator {
 public:
  virtual ~StateEstimator() = default;
  virtual void reset() = 0;
  // fold one sensor frame into the estimate; a frame with NaN/Inf leaves state.valid false
  virtual void update(const SensorFrame& frame, RobotState& state) = 0;
};

}  // namespace cerebellum
