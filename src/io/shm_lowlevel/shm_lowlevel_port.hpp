// The lowlevel.h shared memory at the MC's edge: maps the two objects, reads a flagged command
// frame into a JointCommand, publishes the joint states and the IMU, and prints the source's
// events off the loop thread. It owns the ShmLowLevelSource (lowlevel/shm/) that makes every
// decision, as LcmMotorSdkAdapter owns its MotorSdkSource, and drives it at each 1 ms substep of
// the loop (the source stays free of the loop's interfaces and of the vendor structs).
//
// Wiring: arbiter.add_low_level_source(port.source()); loop.add_substep_participant(port).
#pragma once

#include <atomic>
#include <cstdint>
#include <cstdio>
#include <string>

#include "cycle/substep_participant.hpp"
#include "io/common/link_faults.hpp"
#include "io/shm_lowlevel/shm_codec.hpp"
#include "io/shm_lowlevel/shm_event_log.hpp"
#include "io/shm_lowlevel/shm_lowlevel_config.hpp"
#include "io/shm_lowlevel/shm_region.hpp"
#include "lowlevel/shm/shm_link.hpp"
#include "lowlevel/shm/shm_lowlevel_source.hpp"
#include "safety/command_guard.hpp"

namespace cerebellum {

class ShmLowLevelPort final : public ShmLink, public SubstepParticipant {
 public:
  // creates and maps the two objects (throws std::runtime_error when it cannot, and
  // std::invalid_argument for a command_timeout_cycles < 1 before creating anything); limits gives
  // the gain bounds of a valid frame and the damping of a dropped command; log receives the events
  ShmLowLevelPort(const ShmLowLevelConfig& config, const GuardLimits& limits, std::FILE* log = stderr);
  ~ShmLowLevelPort() override;
  ShmLowLevelPort(const ShmLowLevelPort&) = delete;
  ShmLowLevelPort& operator=(const ShmLowLevelPort&) = delete;

  // the simulation's faults on the command frames (`cerebellum fault link shm ...`); before the
  // loop runs (the loop thread applies them)
  void attach_link_faults(LinkFaults& faults) { link_faults_ = &faults; }

  // register with SourceArbiter::add_low_level_source
  ShmLowLevelSource& source() { return source_; }
  const ShmLowLevelSource& source() const { return source_; }

  // SubstepParticipant, loop thread: one cycle of the source (take the command, publish the
  // state, drive the motors if latched)
  bool on_substep(const SensorFrame& frame, JointCommand& command) override;

  // ShmLink, loop thread (called by the source)
  bool take_command(JointCommand& command) override;
  void publish_state(const SensorFrame& frame) override;
  void report(const ShmEvent& event) override { log_.post(event); }

  const std::string& spline_object_name() const { return spline_.name(); }
  const std::string& imu_object_name() const { return imu_.name(); }
  // waits until every event so far is printed (not from the loop thread)
  void flush_log() { log_.flush(); }

 private:
  spline_data_t* spline() const { return static_cast<spline_data_t*>(spline_.data()); }
  nav_imu_t* imu() const { return static_cast<nav_imu_t*>(imu_.data()); }

  unsigned mode_;
  // first: it checks the configuration before any object is created; it only keeps *this as its
  // link until the loop runs
  ShmLowLevelSource source_;
  ShmRegion spline_;
  ShmRegion imu_;
  ShmEventLog log_;
  std::FILE* log_file_;

  LinkFaults* link_faults_ = nullptr;
  // loop thread only: the frames as the vendor structs hold them
  leg_control_t command_legs_[kNumLegs]{};
  leg_state_t state_legs_[kNumLegs]{};
  nav_imu_t imu_frame_{};
};

}  // namespace cerebellum
