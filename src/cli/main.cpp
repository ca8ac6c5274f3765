// cerebellum: the open motion-control module. Dispatches the subcommands.
#include <cstdio>
#include <string>
#include <string_view>
#include <vector>

#include "cli/cmd_command.hpp"
#include "cli/drive_command.hpp"
#include "cli/fault_command.hpp"
#include "cli/gait_command.hpp"
#include "cli/log_command.hpp"
#include "cli/push_command.hpp"
#include "cli/run_command.hpp"
#include "cli/sim_command.hpp"
#include "cli/sweep_command.hpp"

// the simulator's verbs are linked only into a build with it (CEREBELLUM_WITH_SIM, CMakeLists.txt);
// without it they stay in the table, without a function, so they are named and explained
#if CEREBELLUM_WITH_SIM
#define CEREBELLUM_SIM_VERB(function) &(function)
#else
#define CEREBELLUM_SIM_VERB(function) nullptr
#endif

namespace {

using VerbFunction = int (*)(const std::vector<std::string>&);

struct Verb {
  std::string_view name;
  VerbFunction run;  // nullptr: a verb of the simulator in a build without it
  std::string_view summary;
};

// the one list of the verbs: dispatch, usage and the unknown-command message come from it
constexpr Verb kVerbs[] = {
    {"sim", CEREBELLUM_SIM_VERB(cerebellum::run_sim_command),
     "run the MC on the simulated CyberDog2 (cerebellum sim --help)"},
    {"run", &cerebellum::run_run_command,
     "run the MC on the robot its configuration names, e.g. a CyberDog2 (cerebellum run --help)"},
    {"cmd", &cerebellum::run_cmd_command,
     "send a high-level command to a running MC and keep it alive (cerebellum cmd --help)"},
    {"drive", CEREBELLUM_SIM_VERB(cerebellum::run_drive_command),
     "drive a running MC with a gamepad (cerebellum drive --help)"},
    {"status", &cerebellum::run_status_command,
     "print the MC's high-level responses and odometry (cerebellum status --help)"},
    {"log", &cerebellum::run_log_command,
     "record the interface's LCM traffic, one lcm-logger per port (cerebellum log --help)"},
    {"replay", &cerebellum::run_replay_command, "play a recorded log back on its ports (cerebellum replay --help)"},
    {"push", &cerebellum::run_push_command,
     "push the simulated robot's trunk with a force (cerebellum push --help)"},
    {"fault", &cerebellum::run_fault_command,
     "inject or clear a fault in the simulated robot (cerebellum fault --help)"},
    {"gait", &cerebellum::run_gait_command, "convert and upload self-defined gait files (cerebellum gait --help)"},
    {"sweep", CEREBELLUM_SIM_VERB(cerebellum::run_sweep_command),
     "run a scenario file's grid of lockstep runs, locally or on Slurm (cerebellum sweep --help)"},
};

constexpr const char* kNotInThisBuild = "not in this build: it has no simulator";

std::string usage() {
  std::string text = "usage: cerebellum <command> [options]\ncommands:\n";
  for (const Verb& verb : kVerbs) {
    std::string name(verb.name);
    name.resize(6, ' ');
    text += "  " + name + " " + std::string(verb.summary);
    if (verb.run == nullptr) text += std::string(" [") + kNotInThisBuild + "]";
    text += "\n";
  }
  return text;
}

std::string accepted_names() {
  std::string names;
  for (const Verb& verb : kVerbs) {
    if (verb.run == nullptr) continue;
    names += (names.empty() ? "" : ", ") + std::string(verb.name);
  }
  return names;
}

}  // namespace

int main(int argc, char** argv) {
  const std::vector<std::string> args(argv + 1, argv + argc);
  if (args.empty() || args[0] == "--help" || args[0] == "-h") {
    std::fputs(usage().c_str(), args.empty() ? stderr : stdout);
    return args.empty() ? 2 : 0;
  }
  const std::vector<std::string> rest(args.begin() + 1, args.end());
  for (const Verb& verb : kVerbs) {
    if (verb.name != args[0]) continue;
    if (verb.run != nullptr) return verb.run(rest);
    std::fprintf(stderr,
                 "cerebellum %s: this cerebellum was built without the simulator (CEREBELLUM_WITH_SIM=OFF, e.g. the "
                 "robot's build, docs/robot-build.md); the MC on a robot runs with `cerebellum run --config FILE`\n",
                 args[0].c_str());
    return 2;
  }
  std::fprintf(stderr, "cerebellum: unknown command '%s' (accepted: %s)\n%s", args[0].c_str(),
               accepted_names().c_str(), usage().c_str());
  return 2;
}
