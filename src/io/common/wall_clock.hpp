// Wall-clock seconds for what an interface thread does once per second (logs, keep-alives);
// never used for control, which runs on robot time.
#pragma once

#include <chrono>

namespace cerebellum {

inline double wall_seconds() {
  using Clock = std::chrono::steady_clock;
  return std::chrono::duration<double>(Clock::now().time_since_epoch()).count();
}

}  // namespace cerebellum
