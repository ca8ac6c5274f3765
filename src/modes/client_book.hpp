// What the machine tells each high-level client: its counters and the notes of its refused
// commands, which its interface thread logs. The loop thread writes; each client's thread reads its
// own through its ClientPort.
#pragma once

#include <array>

#include "modes/client_port.hpp"

namespace cerebellum {

class ClientBook {
 public:
  ClientCounters& counters(HighLevelSource source) { return counters_[index(source)]; }
  const ClientCounters& counters(HighLevelSource source) const { return counters_[index(source)]; }
  ClientNoteRing& refusals(HighLevelSource source) { return refusals_[index(source)]; }

  // loop thread: a refused command of the client, counted as a banned transition
  void refused(HighLevelSource source, const ClientNote& note);
  // loop thread: a command or heartbeat of a client that does not hold the robot; noted once per
  // new command (heartbeats and streams repeat it)
  void refused_not_holder(HighLevelSource source, const HighLevelCommand& command, int from_mode,
                          HighLevelSource holder);
  // loop thread: a command taken with values held inside their ranges (reason: static)
  void clamped(HighLevelSource source, const HighLevelCommand& command, const char* reason);
  // loop thread: a mode-62 command dropped while a motion runs
  void motion_dropped(HighLevelSource source, const HighLevelCommand& command);

  // before the loop starts: what the client's interface thread is given
  ClientPort port(HighLevelSource source, CommandInbox& inbox) {
    return ClientPort(source, inbox, refusals_[index(source)], counters_[index(source)]);
  }

 private:
  static std::size_t index(HighLevelSource source) { return static_cast<std::size_t>(source); }

  std::array<ClientCounters, kHighLevelSourceCount> counters_;
  std::array<ClientNoteRing, kHighLevelSourceCount> refusals_;
  std::array<int, kHighLevelSourceCount> refused_life_count_ = no_life_counts();  // the last one noted per client

  static std::array<int, kHighLevelSourceCount> no_life_counts() {
    std::array<int, kHighLevelSourceCount> none{};
    none.fill(-1);
    return none;
  }
};

}  // namespace cerebellum
