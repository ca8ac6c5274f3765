// The options of `cerebellum sweep`, read strictly (an unknown option or a bad value is refused
// with what is accepted).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace cerebellum {

// a sweep larger than this needs --yes: a typo in an axis can make millions of runs
inline constexpr std::uint64_t kSweepConfirmAboveCells = 10000;

struct SlurmOptions {
  std::string partition;  // empty: the cluster's default
  std::string time_limit;  // sbatch --time, e.g. 30 or 1:00:00; empty: the partition's
  int tasks = 0;           // array tasks; 0: one per cell up to 100
  std::string sbatch = "sbatch";  // the program, found on PATH unless a path
  bool wait = true;        // wait for the array and gather
};

struct SweepOptions {
  std::string file;
  std::string out;  // the output folder; empty: sweep-<file stem> beside the cwd
  int jobs = 0;     // 0: all cores
  bool yes = false;
  bool help = false;
  std::optional<std::uint64_t> cell;  // run one cell alone (the worker, or a replay)
  std::string record_path;            // with --cell: a video of the run
  // only cells with cell % count == index (a Slurm task's slice); no gathering
  std::optional<std::pair<std::uint64_t, std::uint64_t>> slice;
  std::string status_dir;  // --status DIR
  std::optional<SlurmOptions> slurm;
};

// throws std::invalid_argument naming the option
SweepOptions parse_sweep_options(const std::vector<std::string>& args);
std::string sweep_usage();

}  // namespace cerebellum
