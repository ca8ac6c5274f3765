// The sweep's worker processes: each cell runs in its own `cerebellum sweep FILE --cell K --out
// DIR` (the same program), its output into the cell's log, at most N at once. A worker that
// crashes or is killed takes only its cell with it: the cell is marked crashed with how it
// ended, and the others go on.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "sweep/sweep_folder.hpp"

namespace cerebellum {

// the running program's own file (/proc/self/exe), so a worker is the very same build
std::string own_executable();

// after each worker: its cell and, when it ended without a result, how it ended
using WorkerDone = std::function<void(std::uint64_t cell, const std::string& crash)>;

// throws std::runtime_error when a worker cannot be started at all
void run_cell_workers(const std::string& executable, const std::string& scenario_path, const SweepFolder& folder,
                      const std::vector<std::uint64_t>& cells, int jobs, const WorkerDone& done);

}  // namespace cerebellum
