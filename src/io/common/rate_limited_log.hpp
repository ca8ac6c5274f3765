// Log lines a client can provoke (refusals, rejected packets), at most a few per second: the rest
// are counted and summed up in one line when the second is over, so a flood cannot fill the log.
#pragma once

#include <atomic>
#include <cstdint>
#include <cstdio>
#include <string>

namespace cerebellum {

class RateLimitedLog {
 public:
  // prefix: "highlevel" -> "highlevel: <line>"; what: the suppressed lines' name in the summary
  RateLimitedLog(std::FILE* out, std::string prefix, std::string what, int lines_per_second);

  // writes the line now, or counts it when this second's lines are used up
  void line(double now_s, const std::string& text);
  // ends the second when it is over: one summary line for what was not shown
  void tick(double now_s);

  // readable from any thread
  std::uint64_t written() const { return written_.load(std::memory_order_relaxed); }
  std::uint64_t suppressed() const { return suppressed_total_.load(std::memory_order_relaxed); }

 private:
  std::FILE* out_;
  std::string prefix_;
  std::string what_;
  int lines_per_second_;
  double window_start_s_ = -1.0e300;
  int lines_in_window_ = 0;
  std::uint64_t suppressed_in_window_ = 0;
  std::atomic<std::uint64_t> written_{0};
  std::atomic<std::uint64_t> suppressed_total_{0};
};

}  // namespace cerebellum
