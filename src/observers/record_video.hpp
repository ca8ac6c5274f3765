// `cerebellum sim --record FILE.mp4`: renders the run headlessly (EGL, software OpenGL) in its
// own thread and pipes the frames to ffmpeg. Frame k shows the first tick at or after k / fps
// seconds of robot time, so the video plays in real time whatever the loop's speed.
// The loop thread only copies a snapshot into a free frame slot (all allocated at start). When no
// slot is free:
//  - lockstep (--speed max): the loop waits for a slot, so every frame is rendered;
//  - paced: the frame is skipped and the previous image repeated, so the loop is never stalled
//    and the video keeps its timing (counted as repeated frames).
// Software rendering of a 1280x720 frame takes longer than a 30 fps frame period, so a paced run
// buffers up to `buffer_frames` snapshots (kPacedVideoBufferS of video, a few hundred bytes each)
// and finish() renders what is left after the run.
#pragma once

#include <array>
#include <condition_variable>
#include <cstdint>
#include <future>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "observers/viewer_snapshot.hpp"
#include "cycle/cycle_observer.hpp"

namespace cerebellum {

struct VideoOptions {
  std::string path;
  double fps = 30.0;
  int width = 1280;
  int height = 720;
  bool lockstep = false;          // the loop runs at full speed: wait for frame slots instead of skipping
  std::size_t buffer_frames = 4;  // frame slots between the loop and the renderer
};

// a paced run buffers this much video (10 minutes: about 10 MB of snapshots at 30 fps)
inline constexpr double kPacedVideoBufferS = 600.0;

struct VideoResult {
  std::uint64_t frames = 0;    // frames in the file
  std::uint64_t repeated = 0;  // of those, repeats of the previous image (rendering fell behind)
  bool ok = false;             // ffmpeg wrote the file
};

class VideoRecorder final : public CycleObserver {
 public:
  // starts the render thread; throws std::runtime_error when the headless context or ffmpeg
  // cannot be started
  VideoRecorder(const Simulation& simulation, const VideoOptions& options);
  ~VideoRecorder() override;
  VideoRecorder(const VideoRecorder&) = delete;
  VideoRecorder& operator=(const VideoRecorder&) = delete;

  void on_cycle(const CycleRecord& record) override;
  // renders what is queued, closes the file; idempotent
  VideoResult finish();
  // snapshots waiting for the renderer (any thread)
  std::size_t queued_frames();

 private:
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
  std::vector<Slot> slots_;
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
