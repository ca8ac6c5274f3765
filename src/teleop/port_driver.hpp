// A pad's commands handed to the MC in its own process (the viewer's keyboard), the way a client's
// messages arrive over a wire: a new command with a new life_count, the running one repeated as the
// heartbeat every kClientHeartbeatPeriodS of robot time. The one producer of its ClientPort: call it
// from one thread only.
#pragma once

#include <cstdint>
#include <optional>

#include "modes/client_port.hpp"
#include "teleop/pad_mapping.hpp"

namespace cerebellum {

class PortDriver {
 public:
  explicit PortDriver(ClientPort port) : port_(port) {}

  // the pad at robot time now_s: a button pressed is sent at once, the sticks are sampled every
  // heartbeat period (a paused robot's time stands still: nothing is sent)
  void drive(const PadState& pad, bool pressed, double now_s);
  // the pad went away: the velocity zeroed, sent once, then no heartbeat (the MC damps 0.5 s later)
  void stop(double now_s);

  // the command running, or nullopt before the first button
  std::optional<HighLevelCommand> current() const { return current_; }
  const PadMapping& mapping() const { return mapping_; }
  // the next refusal of the driver's commands not yet shown
  std::optional<ClientNote> next_note() { return port_.next_note(); }
  // commands the port's ring had no room for (the tick takes a bounded number per client)
  std::uint64_t dropped() const { return dropped_; }

 private:
  // a new command: a new life_count, the heartbeat's grid restarted from now
  void send_new(const HighLevelCommand& command, double now_s);
  // the running command repeated, on the heartbeat period's grid
  void send_heartbeat(double now_s);

  ClientPort port_;
  PadMapping mapping_;
  std::optional<HighLevelCommand> current_;
  int life_count_ = 0;
  bool stopped_ = false;
  double next_sample_s_ = 0.0;
  double next_heartbeat_s_ = 0.0;
  std::uint64_t dropped_ = 0;
};

}  // namespace cerebellum
