// `cerebellum cmd <verb>` (send one high-level command, wait for it, keep it alive) and
// `cerebellum status` (print the MC's responses and odometry): clients of the LCM interface.
#pragma once

#include <string>
#include <vector>

namespace cerebellum {

// return the process exit code
int run_cmd_command(const std::vector<std::string>& args);
int run_status_command(const std::vector<std::string>& args);

}  // namespace cerebellum
