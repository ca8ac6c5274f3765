// `cerebellum log` (lcm-logger, one per interface port) and `cerebellum replay`.
#pragma once

#include <string>
#include <vector>

namespace cerebellum {

// return the process exit code
int run_log_command(const std::vector<std::string>& args);
int run_replay_command(const std::vector<std::string>& args);

}  // namespace cerebellum
