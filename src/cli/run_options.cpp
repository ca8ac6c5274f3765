#include "cli/run_options.hpp"

#include <stdexcept>

#include "cli/option_number.hpp"

namespace cerebellum {

std::string run_usage() {
  return "usage: cerebellum run --config FILE [--duration S]\n"
         "runs the MC on the robot the configuration names (robot.kind), paced by the wall clock;\n"
         "the simulated robot and its tools are `cerebellum sim`'s (docs/real-robot.md)\n"
         "  --config FILE  the MC's configuration, with a robot: section (required)\n"
         "  --duration S   stop after S seconds (S > 0); default: run until Ctrl-C\n";
}

RunCommandOptions parse_run_options(const std::vector<std::string>& args) {
  RunCommandOptions options;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& arg = args[i];
    const auto value = [&]() -> const std::string& {
      if (i + 1 >= args.size()) throw std::invalid_argument(arg + " needs a value");
      return args[++i];
    };
    if (arg == "--help" || arg == "-h") {
      options.help = true;
    } else if (arg == "--config") {
      options.config_path = value();
    } else if (arg == "--duration") {
      const std::string& text = value();
      options.duration_s = option_number(arg, text, "a number of seconds > 0");
      if (options.duration_s <= 0.0) throw std::invalid_argument("--duration: must be > 0, got " + text);
    } else {
      throw std::invalid_argument("unknown option '" + arg + "' (accepted: --config, --duration, --help)");
    }
  }
  if (!options.help && options.config_path.empty()) {
    throw std::invalid_argument("--config FILE is required: the configuration names the robot (robot.kind)");
  }
  return options;
}

}  // namespace cerebellum
