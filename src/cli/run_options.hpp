// Command-line options of `cerebellum run` (the MC on the robot its configuration names).
#pragma once

#include <string>
#include <vector>

namespace cerebellum {

struct RunCommandOptions {
  std::string config_path;   // required: a real robot is never a default
  double duration_s = -1.0;  // < 0: until SIGINT/SIGTERM
  bool help = false;
};

// throws std::invalid_argument naming the option and the accepted values
RunCommandOptions parse_run_options(const std::vector<std::string>& args);
std::string run_usage();

}  // namespace cerebellum
