#include "observers/record_video.hpp"

#include <algorithm>
#include <memory>
#include <vector>

#include "viz/egl_offscreen_context.hpp"
#include "viz/ffmpeg_pipe.hpp"
#include "viz/scene_renderer.hpp"

namespace cerebellum {

VideoRecorder::VideoRecorder(const Simulation& simulation, const VideoOptions& options)
    : options_(options),
      simulation_(simulation),
      capture_(simulation),
      staging_(capture_.sized_snapshot()),
      slots_(std::max<std::size_t>(1, options.buffer_frames)) {
  for (Slot& slot : slots_) slot.snapshot = capture_.sized_snapshot();
  std::promise<void> ready;
  std::future<void> started = ready.get_future();
  thread_ = std::thread([this, &ready] { render_thread(ready); });
  try {
    started.get();
  } catch (...) {
    thread_.join();
    finished_ = true;
    throw;
  }
}

VideoRecorder::~VideoRecorder() { finish(); }

void VideoRecorder::on_cycle(const CycleRecord& record) {
  const double time_s = simulation_.time_s();
  if (!started_) {
    started_ = true;
    start_s_ = time_s;
  }
  const auto due = [&] { return time_s >= start_s_ + static_cast<double>(next_frame_) / options_.fps - 1e-9; };
  if (!due()) return;
  capture_.capture(record, staging_);
  while (due()) enqueue(next_frame_++);
}

void VideoRecorder::enqueue(std::uint64_t frame) {
  std::unique_lock<std::mutex> lock(mutex_);
  if (count_ == slots_.size()) {
    if (!options_.lockstep || failed_) return;  // skipped: the renderer repeats the previous image
    slot_freed_.wait(lock, [&] { return count_ < slots_.size() || failed_; });
    if (failed_) return;
  }
  Slot& slot = slots_[(head_ + count_) % slots_.size()];
  slot.snapshot = staging_;  // same sizes: no allocation
  slot.frame = frame;
  ++count_;
  frame_queued_.notify_one();
}

void VideoRecorder::render_thread(std::promise<void>& ready) {
  // declared in this order so the renderer is freed while the context is still current
  std::unique_ptr<EglOffscreenContext> context;
  std::unique_ptr<SceneRenderer> renderer;
  std::unique_ptr<FfmpegPipe> pipe;
  try {
    context = std::make_unique<EglOffscreenContext>();
    // text about a fifth of the height at 640x480 and below, smaller in small videos
    const int font_scale = options_.height <= 300 ? mjFONTSCALE_50 : mjFONTSCALE_100;
    renderer = std::make_unique<SceneRenderer>(simulation_.model(), options_.width, options_.height, font_scale);
    renderer->use_offscreen_buffer();
    pipe = std::make_unique<FfmpegPipe>(options_.path, options_.width, options_.height, options_.fps);
  } catch (...) {
    ready.set_exception(std::current_exception());
    return;
  }
  ready.set_value();

  const mjrRect viewport{0, 0, options_.width, options_.height};
  std::vector<std::uint8_t> image(pipe->frame_bytes());
  SimSnapshot snapshot = capture_.sized_snapshot();
  VideoResult result;
  bool failed = false;
  const auto write = [&](bool repeat) {
    if (failed) return;
    if (pipe->write_frame(image.data())) {
      ++result.frames;
      if (repeat) ++result.repeated;
      return;
    }
    failed = true;
    std::lock_guard<std::mutex> lock(mutex_);
    failed_ = true;
    slot_freed_.notify_all();
  };

  while (true) {
    std::uint64_t frame = 0;
    {
      std::unique_lock<std::mutex> lock(mutex_);
      frame_queued_.wait(lock, [&] { return count_ > 0 || closing_; });
      if (count_ == 0) break;  // closing, and everything queued is written
      snapshot = slots_[head_].snapshot;
      frame = slots_[head_].frame;
      head_ = (head_ + 1) % slots_.size();
      --count_;
      slot_freed_.notify_one();
    }
    if (failed) continue;
    // frames skipped since the last one show the previous image again
    while (!failed && result.frames > 0 && result.frames < frame) write(true);
    renderer->update(snapshot);
    renderer->render(viewport, status_overlay(snapshot, ""), "");
    renderer->read_rgb(viewport, image.data());
    write(false);
  }
  std::uint64_t total_frames = 0;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    total_frames = total_frames_;
  }
  while (!failed && result.frames > 0 && result.frames < total_frames) write(true);
  result.ok = pipe->finish() && !failed;
  std::lock_guard<std::mutex> lock(mutex_);
  result_ = result;
}

std::size_t VideoRecorder::queued_frames() {
  std::lock_guard<std::mutex> lock(mutex_);
  return count_;
}

VideoResult VideoRecorder::finish() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (finished_) return result_;
    finished_ = true;
    closing_ = true;
    total_frames_ = next_frame_;
    frame_queued_.notify_all();
  }
  thread_.join();
  std::lock_guard<std::mutex> lock(mutex_);
  return result_;
}

}  // namespace cerebellum
