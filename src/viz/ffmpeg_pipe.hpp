// Frames to a file through Debian's ffmpeg: raw RGB frames go down a pipe into an ffmpeg child
// process that encodes them (the container and codec follow the file's extension; .mp4 gives
// H.264). A .png path keeps a single frame, for screenshots.
#pragma once

#include <sys/types.h>

#include <cstdint>
#include <string>

namespace cerebellum {

class FfmpegPipe {
 public:
  // frames: width x height rgb24, rows bottom to top as OpenGL reads them; fps: frames per second
  // of the output. Throws std::runtime_error when ffmpeg cannot be started.
  FfmpegPipe(const std::string& path, int width, int height, double fps);
  ~FfmpegPipe();
  FfmpegPipe(const FfmpegPipe&) = delete;
  FfmpegPipe& operator=(const FfmpegPipe&) = delete;

  // false when ffmpeg no longer takes frames (it has said why on stderr)
  bool write_frame(const std::uint8_t* rgb);
  // end of input; waits for ffmpeg; true when it wrote the file (exit status 0). Idempotent.
  bool finish();

  std::uint64_t frames_written() const { return frames_written_; }
  std::size_t frame_bytes() const { return frame_bytes_; }

 private:
  std::size_t frame_bytes_ = 0;
  int input_fd_ = -1;
  pid_t child_ = -1;
  bool finished_ = false;
  bool succeeded_ = false;
  std::uint64_t frames_written_ = 0;
};

}  // namespace cerebellum
