// The MC side of the lowlevel.h shared-memory interface, without the shared memory: the MC is the
// daemon, the (simulated) robot stands behind it. Every 1 ms of robot time (a ControlLoop substep,
// driven by io/shm_lowlevel's ShmLowLevelPort) it takes the client's command frame if one was
// flagged, has the state published, and, once the arbiter latches it, runs the motors on the
// client's frames: the newest valid one is repeated while no new frame arrives, and after
// command_timeout_cycles missed cycles the command is dropped for damping. Frames with NaN/Inf or
// gains out of bounds are rejected and reported. The memory, the vendor structs and the printing
// are behind ShmLink (lowlevel/shm/shm_link.hpp), so every rule here works on the MC's types.
#pragma once

#include <atomic>
#include <cstdint>

#include "lowlevel/shm/shm_command_rules.hpp"
#include "lowlevel/shm/shm_link.hpp"
#include "modes/source_arbiter.hpp"
#include "safety/command_guard.hpp"

namespace cerebellum {

// a snapshot of the cumulative counts
struct ShmLowLevelCounters {
  std::uint64_t cycles = 0;            // 1 ms updates of the shared memory
  std::uint64_t frames_taken = 0;      // valid command frames read (whether or not in control)
  std::uint64_t frames_rejected = 0;   // frames with NaN/Inf or gains out of bounds
  std::uint64_t missed_cycles = 0;     // cycles without a new valid frame while a command was active
  std::uint64_t command_timeouts = 0;  // times the command was dropped for damping
  std::uint64_t refusals = 0;          // ticks the arbiter refused this source
};

class ShmLowLevelSource final : public LowLevelSource {
 public:
  // link: the shared memory and the event printer, used from the loop thread only (only kept
  // here: the constructor does not call it). command_timeout_cycles: 1 ms cycles without a new
  // valid frame before the command is dropped (throws std::invalid_argument when < 1). limits:
  // the gain bounds of a valid frame and the damping of a dropped command
  ShmLowLevelSource(ShmLink& link, int command_timeout_cycles, const GuardLimits& limits);
  ShmLowLevelSource(const ShmLowLevelSource&) = delete;
  ShmLowLevelSource& operator=(const ShmLowLevelSource&) = delete;

  // LowLevelSource, loop thread
  const char* name() const override { return "the shared-memory low-level client"; }
  bool wants_control() const override { return command_active_; }
  void on_latched(const RobotState& state) override;
  void on_refused(const char* holder) override;
  void compute(const RobotState& state, JointCommand& command) override;

  // loop thread, one 1 ms cycle: take the command, publish the state, drive the motors if
  // latched (then command is replaced and the result is true)
  bool run_cycle(const SensorFrame& frame, JointCommand& command);

  // any thread
  ShmLowLevelCounters counters() const;
  // loop thread (or between lockstep ticks): what the motors get while this source is latched
  const JointCommand& active_command() const { return active_; }
  // false before the first valid frame and after a timeout
  bool command_active() const { return command_active_; }
  bool latched() const { return latched_; }

 private:
  void take_command(const SensorFrame& frame);
  void note_missed_cycle(const SensorFrame& frame);
  static void bump(std::atomic<std::uint64_t>& counter) { counter.fetch_add(1, std::memory_order_relaxed); }

  ShmLink& link_;
  int command_timeout_cycles_;
  CommandLimits command_limits_;  // a frame outside them is rejected
  double damping_kd_;

  // loop thread only
  bool latched_ = false;
  bool command_active_ = false;
  bool timed_out_ = false;         // the last command was dropped; the next valid frame resumes
  bool refusal_reported_ = false;  // one log line per refused stretch of frames
  int missed_in_row_ = 0;
  double last_time_s_ = 0.0;  // robot time of the newest frame, for log lines
  JointCommand active_{};
  JointCommand received_{};  // the frame taken this cycle, before its check

  // the loop thread counts, anyone reads
  std::atomic<std::uint64_t> cycles_{0};
  std::atomic<std::uint64_t> frames_taken_{0};
  std::atomic<std::uint64_t> frames_rejected_{0};
  std::atomic<std::uint64_t> missed_cycles_{0};
  std::atomic<std::uint64_t> command_timeouts_{0};
  std::atomic<std::uint64_t> refusals_{0};
};

}  // namespace cerebellum
