// The ZsiBot as the MC's robot, through its daemon's lowlevel.h shared memory: the MC is the
// daemon's client (the "consumer" of state and "producer" of commands in the header's words). No
// socket, so no receiving thread: the loop thread itself takes the state each 1 ms (read() and
// each substep's advance()) and writes the command frame at 1 kHz, following the flags protocol:
// - state: when state.consumer_flags[CONSUMER_CONTROL] is set, copy state.legs and the IMU, check
//   that the daemon did not start its next update meanwhile (it clears the flags first and ends with
//   a new IMU timestamp: a flag gone or a timestamp moved is a torn copy, not taken), then clear our
//   flag: the SDK's lowlevel_read_state (sdk/lowlevel/lowlevel_sync.h). A flag that stays zero is a daemon that
//   stopped updating: the state watch (io/robot_link) calls the link lost after link_timeout_s.
//   The IMU counts as fresh when its timestamp moved;
// - commands: write cmd.legs, then set cmd.consumer_flags[CONSUMER_CONTROL] (release); a flag
//   still set is a frame the daemon has not taken yet, so the next one waits for its next 1 ms
//   rather than overwrite a frame the daemon may be copying (counted): lowlevel_write_command.
// A small thread prints the link's events off the loop thread. Paced by the wall clock.
#pragma once

#include <atomic>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <string>

#include "backend/hardware_backend.hpp"
#include "core/spsc_ring.hpp"
#include "io/common/adapter_thread.hpp"
#include "io/common/rate_limited_log.hpp"
#include "io/robot_link/listening_window.hpp"
#include "io/robot_link/robot_state_watch.hpp"
#include "io/shm_lowlevel_robot/shm_mapping.hpp"
#include "io/shm_lowlevel_robot/shm_robot_config.hpp"
#include "lowlevel/lowlevel.h"

namespace cerebellum {

// what the client did with the shared memory (loop thread writes; copies travel to the log thread)
struct ShmRobotCounts {
  std::uint64_t states_taken = 0;    // state frames copied whole
  std::uint64_t torn_states = 0;     // copies the daemon overwrote meanwhile: not taken
  std::uint64_t frames_written = 0;  // command frames flagged for the daemon
  std::uint64_t frames_waiting = 0;  // a frame not written: the daemon had not taken the one before
  std::uint64_t frames_late = 0;     // frames left untaken over a whole cycle (the daemon skipped one)
  std::uint64_t damping_frames = 0;  // frames replaced by damping after a motor error
};

class ShmLowLevelRobot final : public HardwareBackend {
 public:
  // maps nothing yet: activate() waits for the daemon's objects
  ShmLowLevelRobot(const ShmRobotConfig& config, std::FILE* log);
  ~ShmLowLevelRobot() override;
  ShmLowLevelRobot(const ShmLowLevelRobot&) = delete;
  ShmLowLevelRobot& operator=(const ShmLowLevelRobot&) = delete;

  SensorFrame read() override;
  void write(const JointCommand& command) override;
  // one substep (1 ms) of real time: take the newest state, and write the command frame again
  // when the last one went out a millisecond ago
  void advance(double period_s) override;
  double time_s() const override { return robot_time_s_; }
  RobotLinkReport link_report() const override;

  // HardwareBackend. activate: until both objects exist and the daemon's joint state and IMU are
  // updating; false when config.activation_timeout_s passes or stop is set
  bool activate(const std::atomic<bool>& stop) override;
  std::string activation_text() const override;
  std::string activation_failure() const override;
  std::string description() const override;
  void finish(std::FILE* out) override;

  // loop thread (or after finish)
  const RobotLinkStatus& link_status() const { return watch_.status(); }
  const ShmRobotCounts& counts() const { return counts_; }

 private:
  struct StatusAt {
    RobotLinkStatus status;
    double robot_time_s = 0.0;
  };

  bool map_objects();
  void take_state();
  void send_frame();
  void log_step();
  spline_data_t* spline() const { return static_cast<spline_data_t*>(spline_->data()); }
  nav_imu_t* imu() const { return static_cast<nav_imu_t*>(imu_->data()); }

  ShmRobotConfig config_;
  std::FILE* log_;
  // loop thread only
  std::unique_ptr<ShmMapping> spline_;
  std::unique_ptr<ShmMapping> imu_;
  std::string not_mapped_why_;
  RobotStateWatch watch_;
  ListeningClock listening_;
  ShmRobotCounts counts_;
  JointCommand command_{};
  bool have_command_ = false;
  double sent_at_s_ = -1.0;  // robot time of the newest frame written
  int waits_in_row_ = 0;     // attempts in a row that found the last frame not taken
  // the round trip in measurement: when the frame went out (wall s; < 0: none), whether the
  // daemon has taken it; the newest measured and the count
  double timed_frame_sent_s_ = -1.0;
  bool timed_frame_taken_ = false;
  double round_trip_s_ = 0.0;
  std::uint64_t round_trips_ = 0;
  std::size_t imu_timestamp_ = 0;
  bool have_imu_timestamp_ = false;
  double robot_time_s_ = 0.0;
  // the loop -> the log thread
  SpscRing<StatusAt, 64> statuses_;
  // log thread only
  StatusAt logged_;
  RateLimitedLog link_log_;
  // last member: started once everything above is built, stopped first
  AdapterThread thread_;
};

}  // namespace cerebellum
