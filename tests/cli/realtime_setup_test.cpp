// The configuration's real-time settings applied to a process, judged on what the kernel then
// reports for it (sched_getscheduler, sched_getaffinity), in a child process so the test runner
// keeps its own scheduling. Whether the system grants them (root, CAP_SYS_NICE) decides which
// line is right, never whether the line matches the kernel.
#include "cli/realtime_setup.hpp"

#include <gtest/gtest.h>
#include <sched.h>
#include <sys/wait.h>
#include <unistd.h>

#include <string>

namespace cerebellum {
namespace {

bool mentions(const RealtimeOutcome& outcome, const std::string& text) {
  for (const std::string& line : outcome.lines) {
    if (line.find(text) != std::string::npos) return true;
  }
  return false;
}

// runs check in a forked child: the exit status says which expectation failed (0: none)
int in_child(int (*check)()) {
  const pid_t child = fork();
  if (child == 0) _exit(check());
  int status = 0;
  waitpid(child, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : 100;
}

TEST(RealtimeSetup, APriorityAndACpuAreSaidAsHadExactlyWhenTheKernelReportsThemForTheProcess) {
  const int failed = in_child([] {
    RealtimeConfig config;
    config.priority = 5;
    config.cpus = {0};
    const RealtimeOutcome outcome = apply_realtime(config);
    if (outcome.lines.size() != 2) return 1;
    const bool rr = sched_getscheduler(0) == SCHED_RR;
    if (rr != mentions(outcome, "SCHED_RR priority 5 for every thread")) return 2;
    if (!rr && !mentions(outcome, "SCHED_RR priority 5 NOT had")) return 3;
    cpu_set_t set;
    CPU_ZERO(&set);
    sched_getaffinity(0, sizeof set, &set);
    const bool pinned = CPU_COUNT(&set) == 1 && CPU_ISSET(0, &set);
    if (pinned != mentions(outcome, "run on CPU 0")) return 4;
    if (outcome.all_had != (rr && pinned)) return 5;
    return 0;
  });
  EXPECT_EQ(failed, 0) << "1: not one line per setting, 2-3: the priority's line, 4: the CPUs' line, 5: all_had";
}

TEST(RealtimeSetup, ACpuTheMachineDoesNotHaveIsRefusedWithTheReasonAndTheProcessRunsOnAnyCpu) {
  const int failed = in_child([] {
    cpu_set_t before;
    CPU_ZERO(&before);
    sched_getaffinity(0, sizeof before, &before);
    RealtimeConfig config;
    config.cpus = {kRealtimeCpuMax};  // a machine with 1024 CPUs would need another test
    const RealtimeOutcome outcome = apply_realtime(config);
    if (outcome.all_had) return 1;
    if (!mentions(outcome, "CPUs 1023 NOT had: Invalid argument (this machine has")) return 2;
    cpu_set_t after;
    CPU_ZERO(&after);
    sched_getaffinity(0, sizeof after, &after);
    return CPU_EQUAL(&before, &after) ? 0 : 3;
  });
  EXPECT_EQ(failed, 0) << "1: said as had, 2: the line, 3: the CPUs changed";
}

TEST(RealtimeSetup, NothingAskedNothingSaidAndNothingChanged) {
  const RealtimeOutcome outcome = apply_realtime(RealtimeConfig{});
  EXPECT_TRUE(outcome.lines.empty());
  EXPECT_TRUE(outcome.all_had);
  EXPECT_EQ(sched_getscheduler(0), SCHED_OTHER);
}

}  // namespace
}  // namespace cerebellum
