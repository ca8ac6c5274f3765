#include "viz/ffmpeg_pipe.hpp"

#include <fcntl.h>
#include <pthread.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <vector>

extern char** environ;

namespace cerebellum {
namespace {

bool ends_with(const std::string& text, const std::string& suffix) {
  return text.size() >= suffix.size() && text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

std::vector<std::string> ffmpeg_arguments(const std::string& path, int width, int height, double fps) {
  char size[32];
  char rate[32];
  std::snprintf(size, sizeof size, "%dx%d", width, height);
  std::snprintf(rate, sizeof rate, "%.6g", fps);
  std::vector<std::string> args = {"ffmpeg",   "-hide_banner", "-loglevel", "error",       "-y",   "-f",
                                   "rawvideo", "-pix_fmt",     "rgb24",     "-video_size", size,   "-framerate",
                                   rate,       "-i",           "pipe:0",    "-vf",         "vflip"};
  if (ends_with(path, ".png")) {
    args.insert(args.end(), {"-frames:v", "1", "-update", "1"});
  } else {
    // 4:2:0 plays everywhere; the index up front lets players start before the end
    args.insert(args.end(), {"-pix_fmt", "yuv420p"});
    if (ends_with(path, ".mp4")) args.insert(args.end(), {"-movflags", "+faststart"});
  }
  args.push_back(path);
  return args;
}

}  // namespace

FfmpegPipe::FfmpegPipe(const std::string& path, int width, int height, double fps)
    : frame_bytes_(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 3) {
  if (width <= 0 || height <= 0 || !(fps > 0.0)) throw std::invalid_argument("ffmpeg: bad frame size or rate");
  int fds[2];
  if (pipe2(fds, O_CLOEXEC) != 0) throw std::runtime_error(std::string("ffmpeg: pipe: ") + std::strerror(errno));

  const std::vector<std::string> args = ffmpeg_arguments(path, width, height, fps);
  std::vector<char*> argv;
  for (const std::string& arg : args) argv.push_back(const_cast<char*>(arg.c_str()));
  argv.push_back(nullptr);

  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, fds[0], STDIN_FILENO);
  const int error = posix_spawnp(&child_, "ffmpeg", &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  close(fds[0]);
  if (error != 0) {
    close(fds[1]);
    child_ = -1;
    throw std::runtime_error(error == ENOENT ? std::string("ffmpeg not found on PATH (Debian package: ffmpeg)")
                                             : std::string("ffmpeg: cannot start: ") + std::strerror(error));
  }
  input_fd_ = fds[1];
}

FfmpegPipe::~FfmpegPipe() { finish(); }

bool FfmpegPipe::write_frame(const std::uint8_t* rgb) {
  if (input_fd_ < 0) return false;
  // a broken pipe (ffmpeg gone) must become an error here, not a SIGPIPE for the whole process
  sigset_t pipe_signal;
  sigset_t previous;
  sigemptyset(&pipe_signal);
  sigaddset(&pipe_signal, SIGPIPE);
  pthread_sigmask(SIG_BLOCK, &pipe_signal, &previous);
  std::size_t done = 0;
  bool ok = true;
  while (done < frame_bytes_) {
    const ssize_t n = write(input_fd_, rgb + done, frame_bytes_ - done);
    if (n > 0) {
      done += static_cast<std::size_t>(n);
    } else if (n < 0 && errno == EINTR) {
      continue;
    } else {
      ok = false;
      if (errno == EPIPE) {
        const timespec no_wait{};
        sigtimedwait(&pipe_signal, nullptr, &no_wait);
      }
      break;
    }
  }
  pthread_sigmask(SIG_SETMASK, &previous, nullptr);
  if (ok) ++frames_written_;
  return ok;
}

bool FfmpegPipe::finish() {
  if (finished_) return succeeded_;
  finished_ = true;
  if (input_fd_ >= 0) close(input_fd_);
  input_fd_ = -1;
  if (child_ < 0) return false;
  int status = 0;
  while (waitpid(child_, &status, 0) < 0 && errno == EINTR) {
  }
  child_ = -1;
  succeeded_ = WIFEXITED(status) && WEXITSTATUS(status) == 0;
  return succeeded_;
}

}  // namespace cerebellum
