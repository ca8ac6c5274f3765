// A sweep's results gathered from its folder: results.csv (one row per run, in cell order; a
// crashed cell's row says crashed with zeros), summary.md (the outcomes, by axis value, and each
// failed run with the command replaying it alone), and the counts `--status` prints.
#pragma once

#include <cstdint>
#include <map>
#include <string>

#include "sweep/scenario.hpp"
#include "sweep/sweep_folder.hpp"

namespace cerebellum {

struct SweepTally {
  std::uint64_t cells = 0;
  std::uint64_t finished = 0;  // with a result (whatever its outcome)
  std::uint64_t crashed = 0;   // the worker ended without a result
  std::uint64_t failed = 0;    // finished with an outcome other than ok
  std::map<std::string, std::uint64_t> outcomes;
  std::uint64_t missing() const { return cells - finished - crashed; }
};

// reads the folder's cells only
SweepTally tally_sweep(const SweepSpec& spec, const SweepFolder& folder);
// writes results.csv and summary.md into the folder
SweepTally gather_sweep(const SweepSpec& spec, const SweepFolder& folder);

// the command that runs one cell alone and prints its row
std::string replay_command(const SweepFolder& folder, std::uint64_t cell);

}  // namespace cerebellum
