// What one high-level client's interface thread sees of the MC: the ring its commands go into, the
// notes of its refused commands, and its own counters. An adapter in io/ holds a ClientPort, never
// the machine: the machine's state belongs to the loop thread, and the adapter only translates.
#pragma once

#include <atomic>
#include <cstdint>
#include <optional>

#include "core/high_level_command.hpp"
#include "core/spsc_ring.hpp"
#include "modes/command_inbox.hpp"

namespace cerebellum {

// what happened to one client's commands in the machine (the loop thread counts, anyone reads)
struct ClientCounters {
  std::atomic<std::uint64_t> received{0};  // taken by the tick while the client held the robot
  std::atomic<std::uint64_t> new_commands{0};
  std::atomic<std::uint64_t> rejected_non_finite{0};
  std::atomic<std::uint64_t> queue_full{0};
  std::atomic<std::uint64_t> motions_dropped{0};  // mode-62 commands while a motion ran
  std::atomic<std::uint64_t> banned_transitions{0};
  std::atomic<std::uint64_t> clamped{0};  // taken with values held inside their ranges
  // the client held the robot and went silent past the heartbeat timeout (get-down protection)
  std::atomic<std::uint64_t> timeouts{0};
  // commands and heartbeats refused while another client holds the robot
  std::atomic<std::uint64_t> refused_not_holder{0};
};

// why a command was refused, or clamped, for the client's interface thread to log (written in
// the loop thread)
struct ClientNote {
  int mode = 0;
  int gait_id = 0;
  int from_mode = 0;
  const char* reason = "";       // a static string
  const char* holder = nullptr;  // the low-level source holding the robot (static), or nullptr
  bool clamped = false;          // taken, with values held inside their ranges (not refused)
};

using ClientNoteRing = SpscRing<ClientNote, 16>;

class ClientPort {
 public:
  ClientPort(HighLevelSource source, CommandInbox& inbox, ClientNoteRing& refusals, const ClientCounters& counters)
      : source_(source), inbox_(&inbox), refusals_(&refusals), counters_(&counters) {}

  HighLevelSource source() const { return source_; }
  // the client's thread (one thread): a received command and the robot time it was read at;
  // false when the ring is full or another thread already hands over for this client
  bool submit(const HighLevelCommand& command, double received_s) {
    return inbox_->push({command, received_s, source_});
  }
  // the client's thread (the one consumer): the next refusal or clamp of its commands not yet logged
  std::optional<ClientNote> next_note() { return refusals_->try_pop(); }
  // any thread
  const SourceInputCounters& input_counters() const { return inbox_->counters(source_); }
  const ClientCounters& counters() const { return *counters_; }

 private:
  HighLevelSource source_;
  CommandInbox* inbox_;
  ClientNoteRing* refusals_;
  const ClientCounters* counters_;
};

}  // namespace cerebellum
