// `cerebellum sim`: the MC on the simulated robot.
#pragma once

#include <string>
#include <vector>

namespace cerebellum {

// returns the process exit code
int run_sim_command(const std::vector<std::string>& args);

}  // namespace cerebellum
