// The process's real-time settings (section `realtime:`, docs/configuration.md): what an MC on a
// robot's board asks of the operating system. Each is optional; what could not be had is said at
// start (cli/realtime_setup.hpp), never silently dropped.
#pragma once

#include <vector>

namespace cerebellum {

// Linux's SCHED_RR priorities are 1..99; its CPU sets (cpu_set_t) hold CPUs 0..1023
constexpr int kRealtimePriorityMax = 99;
constexpr unsigned kRealtimeCpuMax = 1023;

struct RealtimeConfig {
  // SCHED_RR priority (1..99) for every thread of the MC, set before the first thread starts so
  // all inherit it; 0: the normal scheduler
  int priority = 0;
  // mlockall(MCL_CURRENT | MCL_FUTURE): no page of the MC (its code included) is ever paged out,
  // so no step of the loop waits for the disk
  bool lock_memory = false;
  // the CPUs the MC's threads may run on (sched_setaffinity); empty: any
  std::vector<unsigned> cpus;

  bool any() const { return priority > 0 || lock_memory || !cpus.empty(); }
};

}  // namespace cerebellum
