// `cerebellum push FX FY [FZ] --duration S`: a push on the simulated robot's trunk, for people and
// scripts, over the simulation's own channel sim_command (a real robot has none).
#pragma once

#include <string>
#include <vector>

namespace cerebellum {

// 0: the running simulation took the push; 1: refused, or no simulation answered; 2: usage
int run_push_command(const std::vector<std::string>& args);

}  // namespace cerebellum
