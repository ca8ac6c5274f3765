// The client interfaces an MC serves, as its configuration enables them: the shared memory, the
// motor SDK, the CyberDog2 high-level LCM interface, the AlienGo UDP interface and the state
// feedback both CyberDog2 interfaces list; with the high-level interface, the MC's own diagnostics
// for `cerebellum status`. One assembly for `cerebellum sim` and `cerebellum run`.
#pragma once

#include <cstdio>
#include <optional>

#include "io/common/link_faults.hpp"
#include "io/lcm_diagnostics/lcm_diagnostics_publisher.hpp"
#include "io/lcm_highlevel/lcm_highlevel_adapter.hpp"
#include "io/lcm_motor_sdk/lcm_motor_sdk_adapter.hpp"
#include "io/lcm_motor_sdk/lcm_state_feedback.hpp"
#include "io/shm_lowlevel/shm_lowlevel_port.hpp"
#include "io/udp_aliengo/udp_aliengo_adapter.hpp"
#include "loop/mc.hpp"

namespace cerebellum {

class ClientInterfaces {
 public:
  // attaches each enabled interface to mc (arbiter sources, loop observers, substep participants);
  // link_faults: the client links' faults the simulation serves (`cerebellum fault link ...`), or
  // nullptr on a real robot. log: where the interfaces' events go. Throws std::runtime_error
  // naming an endpoint that cannot be opened
  ClientInterfaces(Mc& mc, LinkFaultSet* link_faults, std::FILE* log);
  ClientInterfaces(const ClientInterfaces&) = delete;
  ClientInterfaces& operator=(const ClientInterfaces&) = delete;

  // stops the threads and prints each interface's summary line
  void finish(std::FILE* out);

 private:
  std::optional<ShmLowLevelPort> shm_;
  std::optional<LcmMotorSdkAdapter> motor_sdk_;
  std::optional<LcmHighLevelAdapter> highlevel_;
  std::optional<UdpAliengoAdapter> aliengo_;
  std::optional<LcmStateFeedback> state_feedback_;
  std::optional<LcmDiagnosticsPublisher> diagnostics_;
};

}  // namespace cerebellum
