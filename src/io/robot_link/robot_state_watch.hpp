// What a real robot's state stream must pass before the MC trusts it, whatever carries it (the
// CyberDog2's motor SDK over LCM, the ZsiBot's lowlevel.h shared memory), on the MC's types:
// - a motor reporting an error: the client stops commanding, latched until restart (stopped);
// - the link watch: no fresh joints or IMU for link_timeout_s -> every motor reads "disconnected"
//   in the sensor frame, so the health monitor damps the legs (the silence counted only over the
//   receiver's listening window: listening_window.hpp); once lost, only a fresh state brings it back;
// - a state that repeats or jumps: joints or an IMU equal in every value to the ones before are a
//   stuck sender, not news, so they do not refresh the link (a stream that only repeats is lost
//   after link_timeout_s); joints whose angle moved further since the last ones taken than a joint
//   can (twice its no-load speed over the time between them, and 5 degrees) are refused, and the
//   next ones are compared with the last ones taken (a lasting jump is a lost link).
#pragma once

#include <cstdint>

#include "core/robot_readings.hpp"
#include "core/types.hpp"
#include "io/robot_link/listening_window.hpp"

namespace cerebellum {

// what the watch saw, for the backend's log and summary (the loop thread writes, a copy travels)
struct RobotLinkStatus {
  bool stopped = false;            // a motor reported an error: the client sends damping until restart
  std::uint32_t error_motors = 0;  // bit i: motor i reported an error when the client stopped
  bool link_lost = false;
  double link_silent_s = 0.0;         // at the last frame: since the older of the newest joints and IMU
  std::uint64_t link_losses = 0;      // times the link was lost
  std::uint64_t repeated_states = 0;  // joints or IMU equal to the ones before: not fresh
  std::uint64_t jumped_states = 0;    // joints refused: an angle moved further than a joint can
  double last_jump_rad = 0.0;         // the largest angle step of the newest refused joints
};

// the largest step a joint's angle can make in dt_s: twice the no-load speed (a leg thrown by a
// fall may be driven past it), plus 5 degrees of encoder and timing slack
double joint_step_limit_rad(double dt_s);

class RobotStateWatch {
 public:
  explicit RobotStateWatch(double link_timeout_s) : link_timeout_s_(link_timeout_s) {}

  // each reading as it arrived, received_s on the link's clock (seconds, monotonic)
  void take_joints(const JointReading& joints, double received_s);
  void take_imu(const ImuReading& imu, double received_s);

  // the sensor frame, stamped robot_time_s, with the link judged over the receiver's listening
  // window (on the link's clock): the silence runs from the newer of the last reading and
  // window.since_s to window.until_s, since a receiver that was not running cannot tell a silent
  // robot (a process or a machine paused, as a loaded host does, is not a lost link)
  SensorFrame frame(const ListeningWindow& window, double robot_time_s);

  const RobotLinkStatus& status() const { return status_; }
  // the newest joint angles taken (what a damping frame holds after a motor error)
  const JointArray<double>& q() const { return frame_.q; }

 private:
  double link_timeout_s_;
  RobotLinkStatus status_;
  SensorFrame frame_;
  bool have_joints_ = false;
  bool have_imu_ = false;
  double joints_received_s_ = 0.0;
  double imu_received_s_ = 0.0;
  double lost_at_s_ = 0.0;  // when the link was last lost (link's clock)
};

}  // namespace cerebellum
