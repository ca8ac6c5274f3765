// sim_command texts: a valid push within its limits, a valid fault that reads back from its own
// text, or refused with a reason.
#include <cmath>
#include <string>

#include "fuzz_target.hpp"
#include "io/lcm_sim_control/sim_command_text.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace cerebellum;
  const std::string text(reinterpret_cast<const char*>(data), size);
  const SimCommand command = parse_sim_command(text);
  FUZZ_CHECK(int(command.push.has_value()) + int(command.fault.has_value()) + int(command.link.has_value()) +
                 int(!command.error.empty()) ==
             1);
  if (command.push) {
    for (double f : command.push->force_n) FUZZ_CHECK(std::isfinite(f) && std::abs(f) <= kPushForceMaxN);
    FUZZ_CHECK(command.push->duration_s > 0.0 && command.push->duration_s <= kPushDurationMaxS);
  }
  if (command.fault) {
    const FaultRequest& fault = *command.fault;
    FUZZ_CHECK(std::isfinite(fault.value) && std::isfinite(fault.duration_s) && fault.duration_s >= 0.0);
    FUZZ_CHECK(fault.index >= -1 && fault.index < 12);
    const SimCommand again = parse_sim_command(fault_command_text(fault));
    FUZZ_CHECK(again.fault.has_value() && again.fault->kind == fault.kind && again.fault->index == fault.index);
  }
  if (command.link) {
    const LinkFaultRequest& link = *command.link;
    FUZZ_CHECK(std::isfinite(link.value) && link.value >= 0.0 && link.value <= 10.0);
    const SimCommand again = parse_sim_command(fault_command_text(link));
    FUZZ_CHECK(again.link.has_value() && again.link->field == link.field && again.link->link == link.link);
  }
  return 0;
}
