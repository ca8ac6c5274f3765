// `cerebellum sim --record FILE.mp4`: renders the run headlessly (EGL, software OpenGL) in its
// own thread and pipes the frames to ffmpeg. Frame k shows the first tick at or after k / fps
// seconds of robot time, so the video plays in real time whatever the loop's speed.
// The loop thread only copies a snapshot into a free frame slot. When no slot is free:
//  - lockstep (--speed max): the loop waits for a slot, so every frame is rendered;
//  - paced: the frame is skipped and the previous image repeated, so the loop is never stalled
//    and the video keeps its timing (counted as repeated frames).
#pragma once

#include <array>
#include <condition_variable>
#include <cstdint>
#include <future>
#include <mutex>
#include <string>
#include <thread>

#include "app/viewer_snapshot.hpp"
#include "cycle/cycle_observer.hpp"

namespace cerebellum {

struct VideoOptions {
  std::string path;
  double fps = 30.0;
  int width = 640;
  int height = 480;
  bool lockstep = false;  // the loop runs at full speed: wait for frame slots instead of skipping
};

struct VideoResult {
  std::uint64_t frames = 0;    // frames in the file
  std::uint64_t repeated = 0;  // of those, repeats of the previous image (rendering fell behind)
  bool ok = false;             // ffmpeg wrote the file
};

class VideoRecorder final : public CycleObserver {
 public:
  // starts the render thread; throws std::runtime_error when the headless context or ffmpeg
  // cannot be started
  VideoRecorder(const Simulation& simulation, const HighLevelMachine& machine, const VideoOptions& options);
  ~VideoRecorder() override;
  VideoRecorder(const VideoRecorder&) = delete;
  VideoRecorder& operator=(const VideoRecorder&) = delete;

  void on_cycle(const CycleRecord& record) override;
  // renders what is queued, closes the file; idempotent
  VideoResult finish();

 private:
  static constexpr std::size_t kSlots = 4;
  struct Slot {
    SimSnapshot snapshot;
    std::uint64_t frame = 0;
  };

  void render_thread(std::promise<void>& ready);
  // loop thread: queue frame number `frame` showing staging_
  void enqueue(std::uint64_t frame);

  VideoOptions options_;
  const Simulation& simulation_;
  SnapshotCapture capture_;
  // loop thread
  SimSnapshot staging_;
  bool started_ = false;
  double start_s_ = 0.0;
  std::uint64_t next_frame_ = 0;
  // shared, under mutex_
  std::mutex mutex_;
  std::condition_variable frame_queued_;
  std::condition_variable slot_freed_;
  std::array<Slot, kSlots> slots_;
  std::size_t head_ = 0;
  std::size_t count_ = 0;
  bool closing_ = false;
  bool failed_ = false;             // ffmpeg stopped taking frames: drain without rendering
  std::uint64_t total_frames_ = 0;  // set when closing
  VideoResult result_;
  bool finished_ = false;
  std::thread thread_;
};

}  // namespace cerebellum
