// The MC side of the lowlevel.h shared-memory interface: the MC is the daemon, the (simulated)
// robot stands behind it. Every 1 ms of robot time (a ControlLoop substep) it takes the client's
// command frame if one was flagged, then publishes the joint states and the IMU. Once the
// arbiter latches it, the motors run the client's frames: the newest valid one is repeated while
// no new frame arrives, and after command_timeout_cycles missed cycles the command is dropped
// for damping. Frames with NaN/Inf or gains out of bounds are rejected and logged.
#pragma once

#include <atomic>
#include <cstdint>
#include <cstdio>

#include "cycle/substep_participant.hpp"
#include "io/common/count.hpp"
#include "modes/source_arbiter.hpp"
#include "io/shm_lowlevel/shm_codec.hpp"
#include "io/shm_lowlevel/shm_event_log.hpp"
#include "io/shm_lowlevel/shm_lowlevel_config.hpp"
#include "io/shm_lowlevel/shm_region.hpp"
#include "safety/command_guard.hpp"

namespace cerebellum {

// cumulative, readable from any thread
struct ShmLowLevelCounters {
  Count cycles;            // 1 ms updates of the shared memory
  Count frames_taken;      // valid command frames read (whether or not in control)
  Count frames_rejected;   // frames with NaN/Inf or gains out of bounds
  Count missed_cycles;     // cycles without a new valid frame while a command was active
  Count command_timeouts;  // times the command was dropped for damping
  Count refusals;          // ticks the arbiter refused this source
};

class ShmLowLevelSource final : public LowLevelSource, public SubstepParticipant {
 public:
  // creates and maps the two objects (throws std::runtime_error when it cannot); limits gives the
  // gain bounds of a valid frame and the damping of a dropped command; log receives the events
  ShmLowLevelSource(const ShmLowLevelConfig& config, const GuardLimits& limits, std::FILE* log = stderr);
  ~ShmLowLevelSource() override;
  ShmLowLevelSource(const ShmLowLevelSource&) = delete;
  ShmLowLevelSource& operator=(const ShmLowLevelSource&) = delete;

  // LowLevelSource, loop thread
  const char* name() const override { return "the shared-memory low-level client"; }
  bool wants_control() const override { return command_active_; }
  void on_latched(const RobotState& state) override;
  void on_refused(const char* holder) override;
  void compute(const RobotState& state, JointCommand& command) override;

  // SubstepParticipant, loop thread: take the command, publish the state, drive the motors if latched
  bool on_substep(const SensorFrame& frame, JointCommand& command) override;

  ShmLowLevelCounters counters() const;
  // loop thread (or between lockstep ticks): what the motors get while this source is latched
  const JointCommand& active_command() const { return active_; }
  // false before the first valid frame and after a timeout
  bool command_active() const { return command_active_; }
  bool latched() const { return latched_; }
  const std::string& spline_object_name() const { return spline_.name(); }
  const std::string& imu_object_name() const { return imu_.name(); }
  // waits until every event so far is printed (not from the loop thread)
  void flush_log() { log_.flush(); }

 private:
  void take_command(const SensorFrame& frame);
  void note_missed_cycle(const SensorFrame& frame);
  void publish_state(const SensorFrame& frame);

  spline_data_t* spline() const { return static_cast<spline_data_t*>(spline_.data()); }
  nav_imu_t* imu() const { return static_cast<nav_imu_t*>(imu_.data()); }
  // the 4-byte flags and the 8-byte timestamp are naturally aligned inside the packed layout
  std::atomic_ref<std::uint32_t> state_flag(std::size_t consumer) const;
  std::atomic_ref<std::uint32_t> command_flag() const;
  std::atomic_ref<std::size_t> imu_timestamp() const;

  ShmLowLevelConfig config_;
  CommandLimits command_limits_;  // a frame outside them is rejected
  double damping_kd_;
  ShmRegion spline_;
  ShmRegion imu_;
  ShmEventLog log_;
  std::FILE* log_file_;

  // loop thread only
  bool latched_ = false;
  bool command_active_ = false;
  bool timed_out_ = false;         // the last command was dropped; the next valid frame resumes
  bool refusal_reported_ = false;  // one log line per refused stretch of frames
  int missed_in_row_ = 0;
  double last_time_s_ = 0.0;  // robot time of the newest frame, for log lines
  JointCommand active_{};
  JointCommand decoded_{};
  leg_control_t command_legs_[kNumLegs]{};
  leg_state_t state_legs_[kNumLegs]{};
  nav_imu_t imu_frame_{};

  ShmLowLevelCounters counts_;  // the loop thread counts, anyone reads
};

}  // namespace cerebellum
