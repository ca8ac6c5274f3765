// Applies the configuration's `realtime:` section to this process, before its first thread starts
// (threads inherit the scheduling policy and the CPU set; memory locking covers the process). What
// the system refused (no root or CAP_SYS_NICE, a memlock limit, a CPU that is not there) is said in
// the returned lines and the MC runs without it: a developer's laptop must still run the MC, and a
// robot owner must see that it ran without.
#pragma once

#include <string>
#include <vector>

#include "loop/realtime_config.hpp"

namespace cerebellum {

struct RealtimeOutcome {
  std::vector<std::string> lines;  // one per setting asked for, each "realtime: ..."
  bool all_had = true;             // false when a setting could not be had
};

RealtimeOutcome apply_realtime(const RealtimeConfig& config);

}  // namespace cerebellum
