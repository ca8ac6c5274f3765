// One timed fault of a YAML list (`{at_s, fault, duration_s}`, the fault in the grammar of
// backend/fault_request.hpp), read strictly: shared by the fault scenario files of `cerebellum
// sim --faults` and the scenario files of `cerebellum sweep`.
#pragma once

#include <yaml-cpp/yaml.h>

#include <string>

#include "backend/fault_injecting_backend.hpp"

namespace cerebellum {

// entry_name: "faults[3]" for messages; kind: what the file is ("fault scenario", "scenario");
// at_s within [0, latest_s], duration_s within [1 ms, max_duration_s]; throws ConfigError
TimedFault read_timed_fault(const YAML::Node& node, const std::string& file, const std::string& entry_name,
                            const std::string& kind, double latest_s, double max_duration_s);

}  // namespace cerebellum
