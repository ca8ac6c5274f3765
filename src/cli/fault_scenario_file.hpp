// Fault scenario files (`cerebellum sim --faults FILE.yaml`): the faults to inject and when, in
// simulated seconds from the start, written in the fault grammar of backend/fault_request.hpp:
//   faults:
//     - at_s: 5.0
//       fault: motor FR_knee disconnected
//       duration_s: 4      # optional: it clears itself after this long
//     - at_s: 12
//       fault: battery soc 4
#pragma once

#include <string>
#include <vector>

#include "loop/config_error.hpp"
#include "backend/fault_injecting_backend.hpp"

namespace cerebellum {

// a scenario file larger than this is refused before it is read
inline constexpr std::size_t kFaultScenarioMaxBytes = 64 * 1024;
inline constexpr std::size_t kFaultScenarioMaxEntries = 1000;
inline constexpr double kFaultScenarioMaxTimeS = 24 * 3600.0;

// throws ConfigError naming the file, the entry and what is wrong
std::vector<TimedFault> load_fault_scenario(const std::string& path);
// the same from the file's text; name is the file for messages
std::vector<TimedFault> parse_fault_scenario(const std::string& text, const std::string& name);

}  // namespace cerebellum
