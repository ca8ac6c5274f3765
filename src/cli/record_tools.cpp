#include "cli/record_tools.hpp"

#include <cerrno>
#include <cstring>

#include "cli/video_progress.hpp"
#include "loop/mc.hpp"

namespace cerebellum {

SimTools::SimTools(Mc& mc, const SimOptions& options) : mc_(mc), options_(options) {
  if (!options.telemetry_path.empty()) {
    telemetry_ =
        std::make_unique<TelemetryRecorder>(options.telemetry_path, options.telemetry_rate_hz, mc.simulation());
    mc.loop().add_observer(*telemetry_);
  }
  if (!options.record_path.empty()) {
    VideoOptions video;
    video.path = options.record_path;
    video.fps = options.record_fps;
    video.width = options.record_width;
    video.height = options.record_height;
    video.lockstep = options.speed <= 0.0;
    if (!video.lockstep) video.buffer_frames = static_cast<std::size_t>(options.record_fps * kPacedVideoBufferS);
    video_ = std::make_unique<VideoRecorder>(mc.simulation(), video);
    mc.loop().add_observer(*video_);
  }
  if (options.viewer) viewer_ = std::make_unique<ViewerSession>(mc);
}

RunStats SimTools::run(const RunOptions& run_options, const std::atomic<bool>& stop) {
  if (viewer_) return viewer_->run(run_options, stop, options_.viewer_screenshot_path);
  return mc_.loop().run(run_options, stop);
}

bool SimTools::finish(std::FILE* out, std::FILE* err) {
  bool ok = true;
  if (video_) {
    if (const std::size_t queued = video_->queued_frames(); queued > 0) {
      std::fprintf(out, "video: rendering the last %zu frames buffered during the run (%.1f s of video)...\n", queued,
                   static_cast<double>(queued) / options_.record_fps);
      std::fflush(out);
    }
    // the bar goes where it was asked (a terminal while out is a log), else to out
    std::FILE* progress = out;
    std::FILE* opened = nullptr;
    if (!options_.progress_path.empty()) {
      opened = std::fopen(options_.progress_path.c_str(), "w");
      if (opened == nullptr) {
        std::fprintf(err, "cerebellum sim: --progress-to %s: cannot open it (%s); no bar\n",
                     options_.progress_path.c_str(), std::strerror(errno));
      } else {
        progress = opened;
      }
    }
    const VideoResult video = finish_video_showing_progress(*video_, progress);
    if (opened != nullptr) std::fclose(opened);
    if (video.ok) {
      std::fprintf(out, "video: %llu frames at %g fps (%llu repeated because rendering fell behind) written to %s\n",
                   static_cast<unsigned long long>(video.frames), options_.record_fps,
                   static_cast<unsigned long long>(video.repeated), options_.record_path.c_str());
    } else {
      std::fprintf(err, "cerebellum sim: the video %s was not written completely (see ffmpeg's message above)\n",
                   options_.record_path.c_str());
      ok = false;
    }
  }
  if (telemetry_) {
    const TelemetryResult telemetry = telemetry_->finish();
    if (telemetry.ok) {
      std::fprintf(out, "telemetry: %llu rows written to %s\n", static_cast<unsigned long long>(telemetry.rows),
                   options_.telemetry_path.c_str());
    } else {
      std::fprintf(err, "cerebellum sim: telemetry %s incomplete: %llu rows written, %llu dropped\n",
                   options_.telemetry_path.c_str(), static_cast<unsigned long long>(telemetry.rows),
                   static_cast<unsigned long long>(telemetry.dropped));
      ok = false;
    }
  }
  if (viewer_ && !options_.viewer_screenshot_path.empty()) {
    std::fprintf(out, "viewer: last frame saved to %s\n", options_.viewer_screenshot_path.c_str());
  }
  return ok;
}

}  // namespace cerebellum
