#include "cli/progress_bar.hpp"

#include <unistd.h>

#include <cmath>

namespace cerebellum {

namespace {
constexpr int kBarWidth = 30;
}  // namespace

std::string duration_text(double seconds) {
  const long s = std::lround(std::max(0.0, seconds));
  char text[64];
  if (s >= 3600) {
    std::snprintf(text, sizeof text, "%ld h %02ld min", s / 3600, (s % 3600) / 60);
  } else if (s >= 60) {
    std::snprintf(text, sizeof text, "%ld min %02ld s", s / 60, s % 60);
  } else {
    std::snprintf(text, sizeof text, "%ld s", s);
  }
  return text;
}

std::string progress_line(const std::string& what, std::uint64_t done, std::uint64_t total, double elapsed_s,
                          const std::string& note) {
  const double fraction = total == 0 ? 1.0 : static_cast<double>(done) / static_cast<double>(total);
  const int filled = static_cast<int>(fraction * kBarWidth);
  std::string line = what + " [" + std::string(filled, '#') + std::string(kBarWidth - filled, '.') + "] " +
                     std::to_string(done) + "/" + std::to_string(total);
  if (done > 0 && done < total) {
    // the pace so far: the rest takes as long per item as the items done did
    line += ", " + duration_text(elapsed_s / static_cast<double>(done) * static_cast<double>(total - done)) + " left";
  }
  if (!note.empty()) line += ", " + note;
  return line;
}

ProgressBar::ProgressBar(std::FILE* out, std::string what)
    : out_(out), what_(std::move(what)), shown_(::isatty(::fileno(out)) == 1) {}

void ProgressBar::update(std::uint64_t done, std::uint64_t total, double elapsed_s, const std::string& note) {
  if (!shown_) return;
  // \033[K: clear what a longer previous line left
  std::fprintf(out_, "\r%s\033[K", progress_line(what_, done, total, elapsed_s, note).c_str());
  std::fflush(out_);
  drawn_ = true;
}

void ProgressBar::finish() {
  if (drawn_) std::fputc('\n', out_);
  drawn_ = false;
}

}  // namespace cerebellum
