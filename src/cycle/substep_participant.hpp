// An interface with a faster handshake than the control tick, run at every substep of a period.
#pragma once

#include "core/types.hpp"

namespace cerebellum {

// runs at every substep of a control period (each physics_substep_s of robot time), after the
// control stage on substep 0: it sees the newest sensor frame and may replace the command the
// motors run until the next substep (the loop guards the replacement). For interfaces with a
// faster handshake than the control tick, such as the 1 ms shared-memory interface.
class SubstepParticipant {
 public:
  virtual ~SubstepParticipant() = default;
  // return true when command was replaced
  virtual bool on_substep(const SensorFrame& frame, JointCommand& command) = 0;
};

}  // namespace cerebellum
