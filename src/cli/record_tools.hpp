// The tools `cerebellum sim` attaches on request: the live viewer, the video recorder and the
// telemetry log (docs/tools.md). Created after the other loop observers, they run the loop
// (in its own thread under the viewer) and report what they wrote at the end.
#pragma once

#include <atomic>
#include <cstdio>
#include <memory>

#include "loop/control_loop.hpp"
#include "observers/record_telemetry.hpp"
#include "observers/record_video.hpp"
#include "cli/sim_options.hpp"
#include "observers/viewer_session.hpp"

namespace cerebellum {

class Mc;

class SimTools {
 public:
  // throws std::runtime_error when a requested tool cannot start (no display, no ffmpeg, no EGL,
  // a file that cannot be created)
  SimTools(Mc& mc, const SimOptions& options);

  RunStats run(const RunOptions& run_options, const std::atomic<bool>& stop);
  // closes the files and prints where they are; false when one of them failed
  bool finish(std::FILE* out, std::FILE* err);

 private:
  Mc& mc_;
  SimOptions options_;
  std::unique_ptr<TelemetryRecorder> telemetry_;
  std::unique_ptr<VideoRecorder> video_;
  std::unique_ptr<ViewerSession> viewer_;
};

}  // namespace cerebellum
