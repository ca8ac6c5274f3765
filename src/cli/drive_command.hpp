// `cerebellum drive`: a gamepad client of the high-level LCM interface (docs/driving.md).
#pragma once

#include <string>
#include <vector>

namespace cerebellum {

// returns the process exit code
int run_drive_command(const std::vector<std::string>& args);

}  // namespace cerebellum
