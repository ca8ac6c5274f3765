#include "cli/fault_command.hpp"

#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "cli/sim_command_client.hpp"
#include "backend/fault_request.hpp"
#include "io/common/link_faults.hpp"
#include "io/lcm_highlevel/lcm_highlevel_config.hpp"
#include "io/lcm_sim_control/sim_command_text.hpp"

namespace cerebellum {
namespace {

std::string usage() {
  return "usage: cerebellum fault COMPONENT ... [for SECONDS] [--url URL] [--timeout S]\n"
         "Injects a fault into the running simulation (or clears one); the MC answers it as the robot\n"
         "would (docs/safety.md). Exit status 0 when the simulation took it.\n"
         "  motor N disconnected | over_temperature | driver_fault | under_voltage | over_voltage |\n"
         "          over_current [A|B|C] | overload [1..8] | encoder_lost\n"
         "                                                  the driver reports it and stops its motor;\n"
         "                                                  the over-current's phase (default A), which\n"
         "                                                  of the eight overload bits (default 1)\n"
         "  motor N stuck | derated FRACTION                  a seized joint; a motor with less torque\n"
         "  imu bias RAD_S | stuck | dropout | nan\n"
         "  battery soc PERCENT | drain FACTOR | capacity AH | sag VOLTS\n"
         "  foot LEG slippery [MU]                           ground friction under one foot (default 0.05)\n"
         "  link " + link_names("|") + " drop P | delay S | duplicate P | corrupt P | clear\n"
         "                                                  incoming client packets, the shared memory's\n"
         "                                                  command frames (probabilities 0..1)\n"
         "  clear [motor N | imu | battery | foot LEG]        everything, or one component\n"
         "  N: 0..11 in SDK order or a name such as FR_knee; LEG: 0..3 or FR, FL, RR, RL\n"
         "  for SECONDS   the fault clears itself after this much simulated time\n"
         "  --url URL     the simulation's odometry URL (default " +
         HighLevelLcmConfig{}.odometry_url +
         ")\n"
         "  --timeout S   wall seconds to wait for the simulation's answer (default 2)\n"
         "Examples: cerebellum fault motor 3 disconnected;  cerebellum fault battery soc 15;\n"
         "          cerebellum fault imu stuck for 2;  cerebellum fault clear\n";
}

SimVerbRequest parse(const std::vector<std::string>& args) {
  SimVerbRequest options;
  options.url = HighLevelLcmConfig{}.odometry_url;
  std::vector<std::string> words;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& arg = args[i];
    if (take_sim_verb_option(args, i, options)) continue;
    if (arg.size() > 2 && arg.compare(0, 2, "--") == 0) {
      throw std::invalid_argument("unknown option '" + arg + "' (accepted: --url, --timeout)");
    }
    words.push_back(arg);
  }
  if (options.help) return options;
  // the simulation's own grammar, applied before sending
  if (!words.empty() && words[0] == "link") {
    const LinkFaultParse parsed = parse_link_fault(words);
    if (!parsed.request) throw std::invalid_argument(parsed.error);
    options.text = fault_command_text(*parsed.request);
    return options;
  }
  const FaultParse parsed = parse_fault(words);
  if (!parsed.request) throw std::invalid_argument(parsed.error);
  options.text = fault_command_text(*parsed.request);
  return options;
}

}  // namespace

int run_fault_command(const std::vector<std::string>& args) { return run_sim_verb("fault", args, parse, usage); }

}  // namespace cerebellum
