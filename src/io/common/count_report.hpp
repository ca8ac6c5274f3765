// Per-second count lines of the interface threads: "12 truncated, 3 with NaN/Inf".
#pragma once

#include <cstdint>
#include <string>

namespace cerebellum {

// appends "<count> <what>" (comma separated) when count is not zero
inline void append_count(std::string& text, std::uint64_t count, const char* what) {
  if (count == 0) return;
  text += (text.empty() ? "" : ", ") + std::to_string(count) + " " + what;
}

// true once per period: the first call after start_s + period_s, then every period_s
class EveryPeriod {
 public:
  explicit EveryPeriod(double start_s, double period_s = 1.0) : next_s_(start_s + period_s), period_s_(period_s) {}
  bool due(double now_s) {
    if (now_s < next_s_) return false;
    next_s_ = now_s + period_s_;
    return true;
  }

 private:
  double next_s_;
  double period_s_;
};

}  // namespace cerebellum
