#include "cli/realtime_setup.hpp"

#include <sched.h>
#include <sys/mman.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace cerebellum {
namespace {

std::string reason(int error) {
  std::string text = std::strerror(error);
  if (error == EPERM) text += " (needs root or CAP_SYS_NICE)";
  return text;
}

std::string cpu_list(const std::vector<unsigned>& cpus) {
  std::string text;
  for (const unsigned cpu : cpus) {
    if (!text.empty()) text += ',';
    text += std::to_string(cpu);
  }
  return text;
}

}  // namespace

RealtimeOutcome apply_realtime(const RealtimeConfig& config) {
  RealtimeOutcome outcome;
  auto refused = [&outcome](const std::string& line) {
    outcome.lines.push_back(line);
    outcome.all_had = false;
  };
  if (!config.cpus.empty()) {
    cpu_set_t set;
    CPU_ZERO(&set);
    for (const unsigned cpu : config.cpus) CPU_SET(cpu, &set);
    if (sched_setaffinity(0, sizeof set, &set) == 0) {
      outcome.lines.push_back("realtime: the MC's threads run on CPU " + cpu_list(config.cpus));
    } else {
      refused("realtime: CPUs " + cpu_list(config.cpus) + " NOT had: " + reason(errno) + " (this machine has " +
              std::to_string(sysconf(_SC_NPROCESSORS_ONLN)) + "); the MC runs on any CPU");
    }
  }
  if (config.priority > 0) {
    sched_param param{};
    param.sched_priority = config.priority;
    if (sched_setscheduler(0, SCHED_RR, &param) == 0) {
      outcome.lines.push_back("realtime: SCHED_RR priority " + std::to_string(config.priority) +
                              " for every thread of the MC");
    } else {
      refused("realtime: SCHED_RR priority " + std::to_string(config.priority) + " NOT had: " + reason(errno) +
              "; the MC runs at normal priority and a loaded machine may delay its loop");
    }
  }
  if (config.lock_memory) {
    // MCL_FUTURE too: the threads' stacks and the buffers allocated after this are locked as
    // they are mapped
    if (mlockall(MCL_CURRENT | MCL_FUTURE) == 0) {
      outcome.lines.push_back("realtime: memory locked (mlockall): no page of the MC is paged out");
    } else {
      const int error = errno;
      refused("realtime: memory locking NOT had: " + std::string(std::strerror(error)) +
              (error == ENOMEM || error == EPERM ? " (RLIMIT_MEMLOCK too low: ulimit -l, or run as root)" : "") +
              "; a page the MC needs may have to be read from the disk mid-loop");
    }
  }
  return outcome;
}

}  // namespace cerebellum
