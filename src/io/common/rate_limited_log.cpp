#include "io/common/rate_limited_log.hpp"

#include <utility>

namespace cerebellum {

RateLimitedLog::RateLimitedLog(std::FILE* out, std::string prefix, std::string what, int lines_per_second)
    : out_(out), prefix_(std::move(prefix)), what_(std::move(what)), lines_per_second_(lines_per_second) {}

void RateLimitedLog::tick(double now_s) {
  if (now_s - window_start_s_ < 1.0) return;
  if (suppressed_in_window_ > 0) {
    std::fprintf(out_, "%s: %llu more %s in the last second not shown\n", prefix_.c_str(),
                 static_cast<unsigned long long>(suppressed_in_window_), what_.c_str());
    std::fflush(out_);
  }
  window_start_s_ = now_s;
  lines_in_window_ = 0;
  suppressed_in_window_ = 0;
}

void RateLimitedLog::line(double now_s, const std::string& text) {
  tick(now_s);
  if (lines_in_window_ >= lines_per_second_) {
    ++suppressed_in_window_;
    suppressed_total_.fetch_add(1, std::memory_order_relaxed);
    return;
  }
  ++lines_in_window_;
  written_.fetch_add(1, std::memory_order_relaxed);
  std::fprintf(out_, "%s: %s\n", prefix_.c_str(), text.c_str());
  std::fflush(out_);
}

}  // namespace cerebellum
