// `cerebellum fault ...`: inject or clear a fault in the running simulation, for people and
// scripts, over the simulation's own channel sim_command (a real robot has none).
#pragma once

#include <string>
#include <vector>

namespace cerebellum {

// 0: the running simulation took it; 1: refused, or no simulation answered; 2: usage
int run_fault_command(const std::vector<std::string>& args);

}  // namespace cerebellum
