#include "sweep/sweep_report.hpp"

#include <vector>

#include "sweep/result_row.hpp"
#include "sweep/sweep_grid.hpp"

namespace cerebellum {

namespace {

// the row of a cell whose worker gave no result: the cell's values and zeros
std::string crashed_row(const SweepSpec& spec, std::uint64_t cell) {
  RunResult nothing;
  nothing.outcome = "crashed";
  return result_row(spec, cell, nothing);
}

std::string quoted(const std::string& path) {
  return path.find_first_of(" '\"$`\\") == std::string::npos ? path : "'" + path + "'";
}

struct OutcomeCounts {
  std::map<std::string, std::uint64_t> by_outcome;
  std::uint64_t runs = 0;
};

const std::vector<std::string>& outcome_columns() {
  static const std::vector<std::string> kOutcomes{"ok", "fell", "stopped", "moving", "unsafe", "crashed"};
  return kOutcomes;
}

std::string counts_cells(const OutcomeCounts& c) {
  std::string out = " " + std::to_string(c.runs) + " |";
  for (const std::string& o : outcome_columns()) {
    const auto at = c.by_outcome.find(o);
    out += " " + std::to_string(at == c.by_outcome.end() ? 0 : at->second) + " |";
  }
  return out;
}

std::string outcome_header(const std::string& first) {
  std::string head = "| " + first + " | runs |", rule = "|---|---|";
  for (const std::string& o : outcome_columns()) {
    head += " " + o + " |";
    rule += "---|";
  }
  return head + "\n" + rule + "\n";
}

}  // namespace

std::string replay_command(const SweepFolder& folder, std::uint64_t cell) {
  return "cerebellum sweep " + quoted(folder.scenario_path()) + " --cell " + std::to_string(cell);
}

SweepTally tally_sweep(const SweepSpec& spec, const SweepFolder& folder) {
  SweepTally tally;
  tally.cells = grid_size(spec);
  const int outcome_at = column_index(result_header(spec), "outcome");
  for (std::uint64_t cell = 0; cell < tally.cells; ++cell) {
    if (const auto row = folder.row(cell)) {
      const std::vector<std::string> fields = csv_fields(*row);
      const std::string outcome = outcome_at < static_cast<int>(fields.size()) ? fields[outcome_at] : "?";
      ++tally.finished;
      ++tally.outcomes[outcome];
      tally.failed += outcome != "ok";
    } else if (folder.crash(cell)) {
      ++tally.crashed;
      ++tally.outcomes["crashed"];
    }
  }
  return tally;
}

SweepTally gather_sweep(const SweepSpec& spec, const SweepFolder& folder) {
  const SweepTally tally = tally_sweep(spec, folder);
  const std::string header = result_header(spec);
  const int outcome_at = column_index(header, "outcome");
  std::string csv = header + "\n";
  std::string failures;
  // per axis, per value (in the axis's order): the outcomes
  std::vector<std::vector<OutcomeCounts>> by_value(spec.axes.size());
  for (std::size_t a = 0; a < spec.axes.size(); ++a) by_value[a].resize(spec.axes[a].values.size());
  for (std::uint64_t cell = 0; cell < tally.cells; ++cell) {
    std::string row;
    std::string note;
    if (const auto finished = folder.row(cell)) {
      row = *finished;
    } else if (const auto crash = folder.crash(cell)) {
      row = crashed_row(spec, cell);
      note = *crash;
    } else {
      continue;
    }
    csv += row + "\n";
    const std::string outcome = csv_fields(row)[outcome_at];
    std::uint64_t rest = cell;
    for (std::size_t a = spec.axes.size(); a-- > 0;) {
      OutcomeCounts& c = by_value[a][rest % spec.axes[a].values.size()];
      rest /= spec.axes[a].values.size();
      ++c.runs;
      ++c.by_outcome[outcome];
    }
    if (outcome != "ok") {
      std::string values;
      const std::vector<double> v = cell_values(spec, cell);
      for (std::size_t a = 0; a < v.size(); ++a)
        values += (values.empty() ? "" : ", ") + spec.axes[a].name + " " + axis_value(spec.axes[a], v[a]);
      failures += "| " + std::to_string(cell) + " | " + values + " | " + outcome + (note.empty() ? "" : " (" + note + ")") +
                  " | " + folder.log_path(cell) + " | `" + replay_command(folder, cell) + "` |\n";
    }
  }
  folder.write_file("results.csv", csv);

  std::string md = "# Sweep of " + folder.scenario_path() + "\n\n";
  md += std::to_string(tally.cells) + " cells: " + std::to_string(tally.finished) + " finished, " +
        std::to_string(tally.crashed) + " crashed, " + std::to_string(tally.missing()) + " not run yet\n\n";
  OutcomeCounts all;
  for (const auto& [outcome, count] : tally.outcomes) {
    all.by_outcome[outcome] = count;
    all.runs += count;
  }
  md += outcome_header("") + "| all |" + counts_cells(all) + "\n\n";
  for (std::size_t a = 0; a < spec.axes.size(); ++a) {
    md += outcome_header(spec.axes[a].name);
    for (std::size_t i = 0; i < spec.axes[a].values.size(); ++i) {
      md += "| " + axis_value(spec.axes[a], spec.axes[a].values[i]) + " |" + counts_cells(by_value[a][i]) + "\n";
    }
    md += "\n";
  }
  if (!failures.empty()) {
    md += "## Runs that did not end ok\n\n| cell | values | outcome | log | replay alone |\n|---|---|---|---|---|\n" +
          failures + "\nA replay with `--record FILE.mp4` also films the run.\n";
  }
  folder.write_file("summary.md", md);
  return tally;
}

}  // namespace cerebellum
