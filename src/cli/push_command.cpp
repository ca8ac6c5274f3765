#include "cli/push_command.hpp"

#include <cmath>
#include <cstdio>
#include <optional>
#include <stdexcept>

#include "cli/sim_command_client.hpp"
#include "core/number_text.hpp"
#include "io/lcm_highlevel/lcm_highlevel_config.hpp"
#include "io/lcm_sim_control/sim_command_text.hpp"

namespace cerebellum {
namespace {

struct PushOptions {
  ForcePulse pulse{{0.0, 0.0, 0.0}, 0.2};
  SimVerbRequest request{"", HighLevelLcmConfig{}.odometry_url};  // where the simulation serves sim_command
};

std::string usage() {
  return "usage: cerebellum push FX FY [FZ] [--duration S] [--url URL] [--timeout S]\n"
         "Pushes the simulated robot: a force on the trunk's centre of mass, FX FY FZ in newtons in the\n"
         "world frame, for S seconds of simulated time (the simulation's own channel sim_command; a\n"
         "real robot has none). Exit status 0 when the running simulation took it.\n"
         "  --duration S  (0, 10] s of simulated time (default 0.2)\n"
         "  --url URL     the simulation's odometry URL (default " +
         HighLevelLcmConfig{}.odometry_url +
         ")\n"
         "  --timeout S   wall seconds to wait for the simulation's answer (default 2)\n"
         "The force's magnitude is at most 500 N. Example: a 20 N s shove from the left,\n"
         "  cerebellum push 0 -200 --duration 0.1\n";
}

double number(const std::string& option, const std::string& text) {
  if (const std::optional<double> value = finite_number(text)) return *value;
  throw std::invalid_argument(option + " must be a finite number, got '" + text + "'");
}

PushOptions parse(const std::vector<std::string>& args) {
  PushOptions options;
  std::vector<double> force;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& arg = args[i];
    if (take_sim_verb_option(args, i, options.request)) continue;
    if (arg == "--duration") {
      if (i + 1 >= args.size()) throw std::invalid_argument(arg + " needs a value");
      options.pulse.duration_s = number(arg, args[++i]);
    } else if (arg.size() > 2 && arg.compare(0, 2, "--") == 0) {
      throw std::invalid_argument("unknown option '" + arg + "' (accepted: --duration, --url, --timeout)");
    } else {
      if (force.size() == 3) throw std::invalid_argument("at most three force components, FX FY FZ");
      force.push_back(number("force component " + std::to_string(force.size() + 1), arg));
    }
  }
  if (options.request.help) return options;
  if (force.size() < 2) throw std::invalid_argument("give at least FX and FY (newtons)");
  for (std::size_t k = 0; k < force.size(); ++k) options.pulse.force_n[k] = force[k];
  // the simulation's own rules, applied before sending
  if (const SimCommand check = parse_sim_command(push_command_text(options.pulse)); !check.push) {
    throw std::invalid_argument(check.error);
  }
  return options;
}

SimVerbRequest push_request(const std::vector<std::string>& args) {
  PushOptions options = parse(args);
  if (!options.request.help) options.request.text = push_command_text(options.pulse);
  return options.request;
}

}  // namespace

int run_push_command(const std::vector<std::string>& args) { return run_sim_verb("push", args, push_request, usage); }

}  // namespace cerebellum
