// Helpers for the tools' tests: run a program and read what it printed, work in a fresh
// directory, decode frames with ffmpeg and measure them.
#pragma once

#include <gtest/gtest.h>

#include <sys/wait.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace cerebellum::test {

struct CommandResult {
  int exit_code = -1;
  std::string output;  // stdout and stderr together
};

inline std::string quoted(const std::string& text) {
  std::string out = "'";
  for (char c : text) out += (c == '\'') ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

// runs a shell command line with stderr joined to stdout
inline CommandResult run_command(const std::string& command) {
  CommandResult result;
  std::FILE* pipe = popen((command + " 2>&1").c_str(), "r");
  if (!pipe) return result;
  char buffer[4096];
  std::size_t n = 0;
  while ((n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0) result.output.append(buffer, n);
  const int status = pclose(pipe);
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return result;
}

inline bool on_path(const std::string& program) {
  return run_command("command -v " + quoted(program) + " >/dev/null").exit_code == 0;
}

inline std::string read_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// a fresh directory, removed at the end unless the test failed (then its path is printed)
class ScratchDir {
 public:
  ScratchDir() {
    char pattern[] = "/tmp/cerebellum_tools_XXXXXX";
    path_ = mkdtemp(pattern);
  }
  ~ScratchDir() {
    if (::testing::Test::HasFailure()) {
      std::printf("kept for inspection: %s\n", path_.c_str());
    } else {
      std::filesystem::remove_all(path_);
    }
  }
  std::string operator/(const std::string& name) const { return (path_ / name).string(); }
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

// frame `index` of a video or image as 8-bit gray, width * height bytes (empty on failure)
inline std::vector<std::uint8_t> decode_gray_frame(const std::string& media, int index, int width, int height,
                                                   const ScratchDir& dir) {
  const std::string raw = dir / ("frame" + std::to_string(index) + ".gray");
  const CommandResult decoded = run_command("ffmpeg -v error -y -i " + quoted(media) + " -vf " +
                                            quoted("select=eq(n\\," + std::to_string(index) + ")") +
                                            " -frames:v 1 -f rawvideo -pix_fmt gray " + quoted(raw));
  const std::string bytes = read_file(raw);
  if (decoded.exit_code != 0 || bytes.size() != static_cast<std::size_t>(width) * height) return {};
  return {bytes.begin(), bytes.end()};
}

inline double variance(const std::vector<std::uint8_t>& pixels) {
  if (pixels.empty()) return 0.0;
  double mean = 0.0;
  for (std::uint8_t p : pixels) mean += p;
  mean /= static_cast<double>(pixels.size());
  double sum = 0.0;
  for (std::uint8_t p : pixels) sum += (p - mean) * (p - mean);
  return sum / static_cast<double>(pixels.size());
}

}  // namespace cerebellum::test
