// The seam between the shared-memory source (its decisions, lowlevel/shm/shm_lowlevel_source.hpp)
// and the shared memory itself (io/shm_lowlevel/shm_lowlevel_port.hpp): everything the source
// needs of the edge, in the MC's own types, so the rules carry no vendor struct, flag or mapping
// and can be tested without shared memory. Called on the loop thread only.
#pragma once

#include "core/types.hpp"
#include "lowlevel/shm/shm_event.hpp"

namespace cerebellum {

class ShmLink {
 public:
  virtual ~ShmLink() = default;

  // the command frame the client flagged since the last call, taken off its flag and translated
  // (SDK convention, every value as written: the source checks them); false when none is flagged
  virtual bool take_command(JointCommand& command) = 0;
  // this cycle's joint states and IMU, for the client to read
  virtual void publish_state(const SensorFrame& frame) = 0;
  // an event to print off the loop thread; never blocks
  virtual void report(const ShmEvent& event) = 0;
};

}  // namespace cerebellum
