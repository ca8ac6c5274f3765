// Which high-level client holds the robot: the first one that speaks, until it has been silent
// past the heartbeat timeout; then the next one to speak takes it. Each client is judged by its
// own commands only (their receive times), never by another client's traffic.
#pragma once

#include <optional>

#include "core/high_level_command.hpp"

namespace cerebellum {

class SourceLease {
 public:
  enum class Verdict {
    Holds,      // the source holds the robot (or took it as the first client)
    TakesOver,  // the holder went silent: the source takes the robot now (a new client)
    Refused,    // another client holds the robot
  };

  explicit SourceLease(double silence_timeout_s) : silence_timeout_s_(silence_timeout_s) {}

  // one command of `source`, received at received_s (robot time)
  Verdict judge(HighLevelSource source, double received_s);

  // the client holding the robot; none before the first command
  std::optional<HighLevelSource> holder() const { return holder_; }

 private:
  double silence_timeout_s_;
  std::optional<HighLevelSource> holder_;
  double holder_last_s_ = 0.0;
};

}  // namespace cerebellum
