// Fault scenario files: parse into faults at finite times within the limits, or fail with a
// ConfigError naming the problem; never another exception, never a crash.
#include <cmath>
#include <string>

#include "cli/fault_scenario_file.hpp"
#include "fuzz_target.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace cerebellum;
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const std::vector<TimedFault> scenario = parse_fault_scenario(text, "fuzz.yaml");
    FUZZ_CHECK(scenario.size() <= kFaultScenarioMaxEntries);
    for (const TimedFault& fault : scenario) {
      FUZZ_CHECK(std::isfinite(fault.at_s) && fault.at_s >= 0.0 && fault.at_s <= kFaultScenarioMaxTimeS);
      FUZZ_CHECK(std::isfinite(fault.request.value) && std::isfinite(fault.request.duration_s));
    }
  } catch (const ConfigError&) {
  }
  return 0;
}
