// A high-level client whose protocol has decisions of its own (the AlienGo sport session: the
// vendor's mode table, the mode-3 position controller, the silence timers) runs them here, in the
// tick, on the tick's state: its transport only decodes and hands over. Each tick the machine
// asks the stage for the commands it makes of what arrived, at most a fixed number, and treats
// them as that client's commands (the lease, the queue).
#pragma once

#include <array>
#include <cstddef>

#include "core/high_level_command.hpp"
#include "core/robot_state.hpp"

namespace cerebellum {

class SourceStage {
 public:
  using Commands = std::array<TimedCommand, kCommandsPerSourcePerTick>;

  virtual ~SourceStage() = default;
  // loop thread, once a tick before the machine acts: status is the machine's as of the last tick;
  // fills out from its front and returns how many commands it made
  virtual std::size_t step(const RobotState& state, const HighLevelStatus& status, Commands& out) = 0;
  // loop thread: what the stage adds to the cycle record's high-level report
  virtual void report(HighLevelReport& /*report*/) const {}
};

}  // namespace cerebellum
