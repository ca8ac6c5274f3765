// `cerebellum sweep --slurm`: the sweep as a Slurm job array (sbatch), each task running its
// slice of the grid (`--slice I/N`) into the shared output folder; the submitting command waits
// for the array with a progress bar, then gathers the folder like a local sweep.
#pragma once

#include <cstdint>

#include "cli/sweep_options.hpp"
#include "sweep/sweep_folder.hpp"

namespace cerebellum {

// submits and, unless --no-wait, waits for the array's end; throws std::runtime_error naming
// what was tried when Slurm cannot be reached (the sbatch program, the controller's answer)
void submit_slurm_sweep(const SweepOptions& options, const SweepFolder& folder, std::uint64_t cells);

// the Slurm jobs submitted for the folder, for --status
void print_slurm_jobs(const SweepFolder& folder);

}  // namespace cerebellum
