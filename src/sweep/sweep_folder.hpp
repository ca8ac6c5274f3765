// A sweep's output folder (--out DIR), the one place a sweep's state lives, so a rerun, a Slurm
// task on another node and `--status` all see the same: the scenario file's text as the sweep
// started (scenario.yaml) and where it was (source), then per cell cells/<k>.csv (its header and
// row, written whole by rename) with its log cells/<k>.log, or cells/<k>.crashed when its worker
// ended without a result.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

namespace cerebellum {

class SweepFolder {
 public:
  explicit SweepFolder(std::string dir) : dir_(std::move(dir)) {}

  // creates the folder for the scenario's text, or checks that it already holds a sweep of the
  // same text (a rerun continues it); throws std::runtime_error saying why it cannot be used
  void prepare(const std::string& scenario_text, const std::string& scenario_path) const;
  // the scenario's text and path kept by prepare; throws std::runtime_error when the folder
  // holds no sweep
  std::string scenario_text() const;
  std::string scenario_path() const;

  const std::string& dir() const { return dir_; }
  std::string log_path(std::uint64_t cell) const;
  bool finished(std::uint64_t cell) const;
  // the cell's row (without the header), if it finished
  std::optional<std::string> row(std::uint64_t cell) const;
  void write_result(std::uint64_t cell, const std::string& header, const std::string& row) const;
  void mark_crashed(std::uint64_t cell, const std::string& reason) const;
  std::optional<std::string> crash(std::uint64_t cell) const;
  // writes a file of the folder whole (by rename), e.g. results.csv
  void write_file(const std::string& name, const std::string& text) const;

 private:
  std::string cell_path(std::uint64_t cell, const char* extension) const;
  std::string dir_;
};

}  // namespace cerebellum
