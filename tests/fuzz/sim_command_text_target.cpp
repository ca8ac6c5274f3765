// sim_command texts: a valid push within its limits, or refused with a reason.
#include <cmath>
#include <string>

#include "fuzz_target.hpp"
#include "io/lcm_sim_control/sim_command_text.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  const cerebellum::SimCommand command = cerebellum::parse_sim_command(text);
  FUZZ_CHECK(command.push.has_value() != !command.error.empty());
  if (command.push) {
    for (double f : command.push->force_n) FUZZ_CHECK(std::isfinite(f) && std::abs(f) <= cerebellum::kPushForceMaxN);
    FUZZ_CHECK(command.push->duration_s > 0.0 && command.push->duration_s <= cerebellum::kPushDurationMaxS);
  }
  return 0;
}
