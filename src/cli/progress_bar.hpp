// A progress line for long work: what is being done, a bar, the count and the time left (from
// the pace so far), redrawn in place on a terminal and silent otherwise (a log or a pipe gets no
// carriage returns). The caller gives the elapsed wall time, so the bar itself reads no clock.
#pragma once

#include <cstdint>
#include <cstdio>
#include <string>

namespace cerebellum {

// "3 min 20 s", "1 h 05 min", "12 s"
std::string duration_text(double seconds);

// the line for done of total after elapsed_s (no time left until one item is done)
std::string progress_line(const std::string& what, std::uint64_t done, std::uint64_t total, double elapsed_s,
                          const std::string& note);

class ProgressBar {
 public:
  // shown only when out is a terminal
  ProgressBar(std::FILE* out, std::string what);
  void update(std::uint64_t done, std::uint64_t total, double elapsed_s, const std::string& note = "");
  // ends the line, if one was drawn
  void finish();

 private:
  std::FILE* out_;
  std::string what_;
  bool shown_;
  bool drawn_ = false;
};

}  // namespace cerebellum
