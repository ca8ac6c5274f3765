// Command-line options of `cerebellum sim`.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace cerebellum {

struct SimOptions {
  double speed = 1.0;        // real-time factor; <= 0 means as fast as possible ("max")
  double duration_s = -1.0;  // < 0: until SIGINT/SIGTERM
  std::string config_path;   // empty: built-in defaults
  std::optional<unsigned> seed;
  bool help = false;
};

// throws std::invalid_argument naming the option and the accepted values
SimOptions parse_sim_options(const std::vector<std::string>& args);
std::string sim_usage();

}  // namespace cerebellum
