#include "cli/video_progress.hpp"

#include <algorithm>
#include <chrono>
#include <future>

#include "cli/progress_bar.hpp"

namespace cerebellum {

VideoResult finish_video_showing_progress(VideoRecorder& recorder, std::FILE* out) {
  const std::size_t total = recorder.queued_frames();
  if (total == 0) return recorder.finish();
  ProgressBar bar(out, "rendering the video");
  const auto start = std::chrono::steady_clock::now();
  // finish() blocks until the render thread has drained its queue; the bar watches the queue
  std::future<VideoResult> done = std::async(std::launch::async, [&recorder] { return recorder.finish(); });
  while (done.wait_for(std::chrono::milliseconds(500)) != std::future_status::ready) {
    const std::size_t left = std::min(recorder.queued_frames(), total);
    bar.update(total - left, total, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(),
               "frames");
  }
  bar.finish();
  return done.get();
}

}  // namespace cerebellum
