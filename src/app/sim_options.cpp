#include "app/sim_options.hpp"

#include <cmath>
#include <stdexcept>

namespace cerebellum {
namespace {

double parse_number(const std::string& option, const std::string& text, const std::string& accepted) {
  std::size_t used = 0;
  double value = 0.0;
  try {
    value = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != text.size() || text.empty() || !std::isfinite(value)) {
    throw std::invalid_argument(option + ": '" + text + "' is not " + accepted);
  }
  return value;
}

}  // namespace

std::string sim_usage() {
  return "usage: cerebellum sim [--speed X|max] [--duration S] [--config FILE] [--seed N]\n"
         "  --speed X     pace at X times real time (X > 0, default 1); 'max' runs lockstep at full speed\n"
         "  --duration S  stop after S seconds of robot time (S > 0); default: run until Ctrl-C\n"
         "  --config FILE YAML configuration (see docs/configuration.md)\n"
         "  --seed N      seed of the sensor noise (integer >= 0)\n";
}

SimOptions parse_sim_options(const std::vector<std::string>& args) {
  SimOptions options;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& arg = args[i];
    auto value = [&]() -> const std::string& {
      if (i + 1 >= args.size()) throw std::invalid_argument(arg + " needs a value\n" + sim_usage());
      return args[++i];
    };
    if (arg == "--help" || arg == "-h") {
      options.help = true;
    } else if (arg == "--speed") {
      const std::string& text = value();
      if (text == "max") {
        options.speed = 0.0;
      } else {
        options.speed = parse_number(arg, text, "a number > 0 or 'max'");
        if (options.speed <= 0.0) throw std::invalid_argument("--speed: must be > 0 or 'max', got " + text);
      }
    } else if (arg == "--duration") {
      const std::string& text = value();
      options.duration_s = parse_number(arg, text, "a number of seconds > 0");
      if (options.duration_s <= 0.0) throw std::invalid_argument("--duration: must be > 0, got " + text);
    } else if (arg == "--config") {
      options.config_path = value();
    } else if (arg == "--seed") {
      const std::string& text = value();
      const double seed = parse_number(arg, text, "an integer >= 0");
      if (seed < 0 || seed != std::floor(seed) || seed > 4294967295.0) {
        throw std::invalid_argument("--seed: must be an integer in [0, 4294967295], got " + text);
      }
      options.seed = static_cast<unsigned>(seed);
    } else {
      throw std::invalid_argument("unknown option '" + arg + "'\n" + sim_usage());
    }
  }
  return options;
}

}  // namespace cerebellum
