// `cerebellum gait`: user gait files for a running MC. `convert` prints the uploaded form of
// human-form parameters; `upload` sends a definition and parameters on user_gait_file and prints
// the MC's two answers (docs/user-gaits.md).
#pragma once

#include <string>
#include <vector>

namespace cerebellum {

int run_gait_command(const std::vector<std::string>& args);

}  // namespace cerebellum
