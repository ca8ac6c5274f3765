// `cerebellum sweep`: a scenario file's grid of lockstep runs on local cores or on Slurm
// (docs/sweeps.md).
#pragma once

#include <string>
#include <vector>

namespace cerebellum {

int run_sweep_command(const std::vector<std::string>& args);

}  // namespace cerebellum
