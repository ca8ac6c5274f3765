// The log lines of a robot's state watch (robot_state_watch.hpp), the same for every transport:
// the link lost and back, states refused as jumps, repeated states, and the stop on a motor error,
// each written when the status changes. Called by a backend's own thread, never the loop's.
#pragma once

#include <cstdio>

#include "io/common/rate_limited_log.hpp"
#include "io/robot_link/robot_state_watch.hpp"

namespace cerebellum {

// how the transport names things, for the lines: "cyberdog2", "spi_data or state_estimator", "spi_data"
struct RobotLinkWords {
  const char* robot;
  const char* state;
  const char* joints;
};

// one line per change from was to is, at robot_time_s: the link's events through events (rate
// limited: a flapping link can provoke many), the motor error once on out, never limited
void log_link_changes(const RobotLinkStatus& was, const RobotLinkStatus& is, double robot_time_s,
                      double link_timeout_s, const RobotLinkWords& words, double now_s, RateLimitedLog& events,
                      std::FILE* out);

}  // namespace cerebellum
