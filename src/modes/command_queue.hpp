// The high-level command semantics of the CyberDog2 MC: heartbeat timeout, life_count, the
// duration queue in control ticks, and the hold command when a timed sequence ends.
#pragma once

#include <cstdint>
#include <vector>

#include "core/high_level_command.hpp"

namespace cerebellum {

class CommandQueue {
 public:
  static constexpr double kHeartbeatTimeoutS = 0.5;
  // timed entries waiting: the seed's customized-gait example queues its steps and then 75 timed
  // "heartbeats" (each a new life_count repeating the last step), about 90 in all; 256 leaves room
  static constexpr std::size_t kCapacity = 256;

  enum class Receipt {
    Heartbeat,  // same life_count: refreshes the timer only
    RunsNow,    // duration 0: replaced the queue
    Queued,     // duration > 0: appended
    Ignored,    // mode -1
    Rejected,   // NaN/Inf in a field: refreshes the timer, changes nothing else
    QueueFull,  // more than kCapacity timed entries waiting
    Dropped,    // a mode-62 command while a motion runs (the reference drops it)
  };

  explicit CommandQueue(double tick_period_s);

  // motion_running: a motion (mode 62) runs now, so a new mode-62 command is dropped
  Receipt receive(const HighLevelCommand& command, double time_s, bool motion_running = false);
  // one control tick has passed; while `switching` the running entry's time does not count;
  // while `hold_front` the running entry does not end (its time counts down to its last tick)
  void tick(bool switching, bool hold_front = false);
  // a client has spoken and then been silent for 0.5 s
  bool timed_out(double time_s) const;
  // forget every entry and the client (after a timeout or a mode forced by the MC); the last
  // life_count is kept: the same client's heartbeats must not run its old command again
  void clear();
  // another client takes over: clear(), and its first command counts whatever its life_count
  void start_new_client();
  // the machine refused current(): take it out as if it had never been sent. When it came in
  // with the last receive(), the queue is as it was before that receive (entries it replaced
  // come back, the generation does not change: nothing new to apply). Otherwise the next entry,
  // or the hold after the last finished one, becomes current (a new generation).
  void withdraw_current();

  // the entry that should run now, or nullptr
  const HighLevelCommand* current() const;
  // changes whenever current() changes to another entry
  std::uint64_t generation() const { return generation_; }
  std::size_t size() const { return entries_.size(); }

 private:
  struct Entry {
    HighLevelCommand command;
    long ticks_left;  // < 0: runs until replaced
  };
  void start_front();

  double tick_period_s_;
  std::vector<Entry> entries_;
  std::vector<Entry> before_last_receive_;        // entries_ as they were before the last receive()
  std::uint64_t generation_of_last_receive_ = 0;  // generation_ right after it; 0: none since
  HighLevelCommand last_finished_;                // the last timed entry that ran out
  int last_life_count_ = -1;
  bool client_seen_ = false;
  double last_receive_s_ = 0.0;
  std::uint64_t generation_ = 0;
};

// the command that holds the robot after a timed entry of `last` ran out: the reference's (3 ->
// 3/1, 11 -> 11/1 or 11/31, anything else -> 21/3), or `last` itself, endless, where that hold
// may not follow it (PureDamper)
HighLevelCommand hold_command_after(const HighLevelCommand& last);

}  // namespace cerebellum
