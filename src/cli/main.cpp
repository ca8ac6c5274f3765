// cerebellum: the open motion-control module. Dispatches the subcommands.
#include <cstdio>
#include <string>
#include <vector>

#include "cli/cmd_command.hpp"
#include "cli/drive_command.hpp"
#include "cli/gait_command.hpp"
#include "cli/log_command.hpp"
#include "cli/fault_command.hpp"
#include "cli/push_command.hpp"
#include "cli/run_command.hpp"
#include "cli/sim_command.hpp"
#include "cli/sweep_command.hpp"

namespace {

constexpr const char* kUsage =
    "usage: cerebellum <command> [options]\n"
    "commands:\n"
    "  sim    run the MC on the simulated CyberDog2 (cerebellum sim --help)\n"
    "  run    run the MC on the robot its configuration names, e.g. a CyberDog2 (cerebellum run --help)\n"
    "  cmd    send a high-level command to a running MC and keep it alive (cerebellum cmd --help)\n"
    "  drive  drive a running MC with a gamepad (cerebellum drive --help)\n"
    "  status print the MC's high-level responses and odometry (cerebellum status --help)\n"
    "  log    record the interface's LCM traffic, one lcm-logger per port (cerebellum log --help)\n"
    "  replay play a recorded log back on its ports (cerebellum replay --help)\n"
    "  push   push the simulated robot's trunk with a force (cerebellum push --help)\n"
    "  fault  inject or clear a fault in the simulated robot (cerebellum fault --help)\n"
    "  gait   convert and upload self-defined gait files (cerebellum gait --help)\n"
    "  sweep  run a scenario file's grid of lockstep runs, locally or on Slurm (cerebellum sweep --help)\n";

}  // namespace

int main(int argc, char** argv) {
  const std::vector<std::string> args(argv + 1, argv + argc);
  if (args.empty() || args[0] == "--help" || args[0] == "-h") {
    std::fputs(kUsage, args.empty() ? stderr : stdout);
    return args.empty() ? 2 : 0;
  }
  const std::vector<std::string> rest(args.begin() + 1, args.end());
  if (args[0] == "sim") return cerebellum::run_sim_command(rest);
  if (args[0] == "run") return cerebellum::run_run_command(rest);
  if (args[0] == "cmd") return cerebellum::run_cmd_command(rest);
  if (args[0] == "drive") return cerebellum::run_drive_command(rest);
  if (args[0] == "status") return cerebellum::run_status_command(rest);
  if (args[0] == "log") return cerebellum::run_log_command(rest);
  if (args[0] == "replay") return cerebellum::run_replay_command(rest);
  if (args[0] == "push") return cerebellum::run_push_command(rest);
  if (args[0] == "fault") return cerebellum::run_fault_command(rest);
  if (args[0] == "gait") return cerebellum::run_gait_command(rest);
  if (args[0] == "sweep") return cerebellum::run_sweep_command(rest);
  std::fprintf(
      stderr,
      "cerebellum: unknown command '%s' (accepted: sim, run, cmd, drive, status, log, replay, push, fault, gait, sweep)\n%s",
      args[0].c_str(), kUsage);
  return 2;
}
