#include "cli/sweep_command.hpp"

#include <sys/prctl.h>

#include <csignal>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <stdexcept>
#include <thread>

#include "cli/progress_bar.hpp"
#include "cli/sweep_options.hpp"
#include "cli/sweep_slurm.hpp"
#include "cli/sweep_workers.hpp"
#include "core/text_file.hpp"
#include "cli/video_progress.hpp"
#include "observers/record_video.hpp"
#include "sweep/result_row.hpp"
#include "sweep/scenario_file.hpp"
#include "sweep/scenario_run.hpp"
#include "sweep/sweep_grid.hpp"
#include "sweep/sweep_report.hpp"

namespace cerebellum {

namespace {

constexpr int kExitOk = 0, kExitRunsFailed = 1, kExitBadInput = 2, kExitIncomplete = 3;

std::string file_text(const std::string& path) {
  std::string error;
  const auto text = read_text_file(path, kScenarioMaxBytes, error);
  if (!text) throw ConfigError("scenario " + path + ": " + error);
  return *text;
}

std::string grid_shape(const SweepSpec& spec) {
  std::string shape;
  for (const Axis& axis : spec.axes)
    shape += (shape.empty() ? "" : " x ") + axis.name + " " + std::to_string(axis.values.size());
  return shape.empty() ? "no axes" : shape;
}

// a replay's video: the recorder on the MC's cycles, every frame rendered (lockstep), the file
// closed before the MC goes; nothing without a path
RunAttachments video_attachments(const std::string& path) {
  if (path.empty()) return {};
  auto recorder = std::make_shared<std::unique_ptr<VideoRecorder>>();
  RunAttachments attachments;
  attachments.started = [recorder, path](Mc& mc) {
    VideoOptions video;
    video.path = path;
    video.lockstep = true;
    *recorder = std::make_unique<VideoRecorder>(mc.simulation(), video);
    mc.loop().add_observer(**recorder);
  };
  attachments.ending = [recorder, path](Mc&) {
    const VideoResult video = finish_video_showing_progress(**recorder, stderr);
    if (!video.ok) throw std::runtime_error("the video " + path + " was not written completely (see ffmpeg's message above)");
    std::fprintf(stderr, "cerebellum sweep: video of %llu frames written to %s\n",
                 static_cast<unsigned long long>(video.frames), path.c_str());
  };
  return attachments;
}

// one cell here, in this process: the worker's job and the replay of a failed run
int run_one_cell(const SweepOptions& o, const SweepSpec& spec, const std::string& text) {
  const std::uint64_t size = grid_size(spec);
  if (*o.cell >= size) {
    std::fprintf(stderr, "cerebellum sweep: --cell %llu is outside the grid of %llu cells (0..%llu)\n",
                 static_cast<unsigned long long>(*o.cell), static_cast<unsigned long long>(size),
                 static_cast<unsigned long long>(size - 1));
    return kExitBadInput;
  }
  std::optional<SweepFolder> folder;
  if (!o.out.empty()) {
    // a worker of a sweep that was stopped has no one to report to: it ends with its sweep
    // rather than run on for hours
    ::prctl(PR_SET_PDEATHSIG, SIGKILL);
    folder.emplace(o.out);
    // a worker must run the scenario its sweep started with, not an edited file
    if (folder->scenario_text() != text)
      throw std::runtime_error(o.file + " has changed since the sweep in " + o.out + " started");
  }
  const Scenario scenario = cell_scenario(spec, *o.cell);
  if (scenario.model_error) {
    std::fprintf(stderr, "cerebellum sweep: cell %llu's robot: %s\n", static_cast<unsigned long long>(*o.cell),
                 describe_model_error(draw_model_error(*scenario.model_error, scenario.seed)).c_str());
  }
  const RunResult result = run_scenario(scenario, video_attachments(o.record_path));
  for (const std::string& note : result.fall_notes)
    std::fprintf(stderr, "cerebellum sweep: cell %llu: %s\n", static_cast<unsigned long long>(*o.cell), note.c_str());
  const std::string header = result_header(spec), row = result_row(spec, *o.cell, result);
  std::printf("%s\n%s\n", header.c_str(), row.c_str());
  if (folder) folder->write_result(*o.cell, header, row);
  return result.outcome == "ok" ? kExitOk : kExitRunsFailed;
}

int exit_status(const SweepTally& tally) {
  if (tally.crashed > 0 || tally.missing() > 0) return kExitIncomplete;
  return tally.failed > 0 ? kExitRunsFailed : kExitOk;
}

void print_tally(const SweepTally& tally, const std::string& dir) {
  std::printf("%llu cells: %llu finished (", static_cast<unsigned long long>(tally.cells),
              static_cast<unsigned long long>(tally.finished));
  bool first = true;
  for (const auto& [outcome, count] : tally.outcomes) {
    if (outcome == "crashed") continue;
    std::printf("%s%s %llu", first ? "" : ", ", outcome.c_str(), static_cast<unsigned long long>(count));
    first = false;
  }
  std::printf("), %llu crashed, %llu not run yet\nresults: %s/results.csv, summary: %s/summary.md\n",
              static_cast<unsigned long long>(tally.crashed), static_cast<unsigned long long>(tally.missing()),
              dir.c_str(), dir.c_str());
}

int run_local(const SweepOptions& o, const SweepSpec& spec, const SweepFolder& folder) {
  const std::uint64_t size = grid_size(spec);
  std::vector<std::uint64_t> cells;
  std::uint64_t kept = 0;
  for (std::uint64_t cell = 0; cell < size; ++cell) {
    if (o.slice && cell % o.slice->second != o.slice->first) continue;
    if (folder.finished(cell)) {
      ++kept;
    } else {
      cells.push_back(cell);
    }
  }
  const int jobs = o.jobs > 0 ? o.jobs : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  std::fprintf(stderr, "cerebellum sweep: %llu cells (%s), %llu already finished in %s, %zu to run on %d workers\n",
               static_cast<unsigned long long>(size), grid_shape(spec).c_str(),
               static_cast<unsigned long long>(kept), folder.dir().c_str(), cells.size(), jobs);
  ProgressBar bar(stdout, "sweep");
  const auto start = std::chrono::steady_clock::now();
  std::uint64_t done = 0, crashed = 0;
  bar.update(0, cells.size(), 0.0);
  run_cell_workers(own_executable(), o.file, folder, cells, jobs, [&](std::uint64_t cell, const std::string& crash) {
    ++done;
    if (!crash.empty()) {
      ++crashed;
      folder.mark_crashed(cell, crash);
      bar.finish();
      std::fprintf(stderr, "cerebellum sweep: cell %llu crashed (%s); its log: %s\n",
                   static_cast<unsigned long long>(cell), crash.c_str(), folder.log_path(cell).c_str());
    }
    const double elapsed_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    bar.update(done, cells.size(), elapsed_s, crashed > 0 ? std::to_string(crashed) + " crashed" : "");
  });
  bar.finish();
  if (o.slice) return crashed > 0 ? kExitIncomplete : kExitOk;  // the submitting side gathers
  const SweepTally tally = gather_sweep(spec, folder);
  print_tally(tally, folder.dir());
  return exit_status(tally);
}

int show_status(const std::string& dir) {
  const SweepFolder folder(dir);
  const std::string text = folder.scenario_text();
  const SweepSpec spec = parse_scenario(text, folder.scenario_path(),
                                        std::filesystem::path(folder.scenario_path()).parent_path().string());
  std::printf("%s\n", progress_line("sweep", tally_sweep(spec, folder).finished, grid_size(spec), 0.0, "").c_str());
  const SweepTally tally = gather_sweep(spec, folder);
  print_tally(tally, dir);
  print_slurm_jobs(folder);
  return exit_status(tally);
}

}  // namespace

int run_sweep_command(const std::vector<std::string>& args) {
  SweepOptions o;
  try {
    o = parse_sweep_options(args);
  } catch (const std::invalid_argument& e) {
    std::fprintf(stderr, "cerebellum sweep: %s\n", e.what());
    return kExitBadInput;
  }
  if (o.help) {
    std::fputs(sweep_usage().c_str(), stdout);
    return kExitOk;
  }
  try {
    if (!o.status_dir.empty()) return show_status(o.status_dir);
    const std::string text = file_text(o.file);
    const SweepSpec spec = parse_scenario(text, o.file, std::filesystem::path(o.file).parent_path().string());
    if (o.cell) return run_one_cell(o, spec, text);
    const std::uint64_t size = grid_size(spec);
    if (size >= kGridSizeCap) {
      std::fprintf(stderr, "cerebellum sweep: %s: the grid (%s) has more than 2^40 cells; no sweep is that large\n",
                   o.file.c_str(), grid_shape(spec).c_str());
      return kExitBadInput;
    }
    if (size > kSweepConfirmAboveCells && !o.yes) {
      std::fprintf(stderr, "cerebellum sweep: %s: the grid (%s) has %llu cells, more than %llu; give --yes to run them all\n",
                   o.file.c_str(), grid_shape(spec).c_str(), static_cast<unsigned long long>(size),
                   static_cast<unsigned long long>(kSweepConfirmAboveCells));
      return kExitBadInput;
    }
    const SweepFolder folder(o.out);
    folder.prepare(text, o.file);
    if (o.slurm) {
      submit_slurm_sweep(o, folder, size);
      if (!o.slurm->wait) return kExitOk;
      const SweepTally tally = gather_sweep(spec, folder);
      print_tally(tally, folder.dir());
      return exit_status(tally);
    }
    return run_local(o, spec, folder);
  } catch (const ConfigError& e) {
    std::fprintf(stderr, "cerebellum sweep: %s\n", e.what());
    return kExitBadInput;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "cerebellum sweep: %s\n", e.what());
    return o.cell ? kExitIncomplete : kExitBadInput;
  }
}

}  // namespace cerebellum
