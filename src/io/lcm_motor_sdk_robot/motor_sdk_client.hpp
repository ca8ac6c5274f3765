// The rules of a motor SDK client, as the vendor's client library keeps them, on the MC's types and
// without sockets (the backend's thread decodes the wire, the loop thread applies these):
// - activation: all-zero frames until the robot reports motor_ctrl_state without err_flag bit 1,
//   and again whenever bit 1 comes back (the robot is then damping and waits for zero frames);
// - a motor reporting an error: stop commanding at once (damping frames, latched until restart);
// - the vendor's command ranges and position-jump steps applied before sending, counted;
// - the link watch: no fresh spi_data or state_estimator for link_timeout_s -> every motor reads
//   "disconnected" in the sensor frame, so the health monitor damps the legs (silence counted only
//   over the receiver's listening window: listening_window.hpp);
// - a state that repeats or jumps: a spi_data or state_estimator equal in every value to the one
//   before it is a stuck sender, not news, so it does not refresh the link (a stream that only
//   repeats is lost after link_timeout_s); a spi_data whose angle moved further since the last one
//   than a joint can (twice its no-load speed over the time between them, and 5 degrees) is
//   refused, and the next ones are compared with the last one taken (a lasting jump is a lost link).
#pragma once

#include <cstdint>

#include "core/types.hpp"
#include "io/lcm_motor_sdk/motor_sdk_wire.hpp"
#include "io/lcm_motor_sdk/robot_state_messages.hpp"
#include "io/lcm_motor_sdk_robot/listening_window.hpp"
#include "io/lcm_motor_sdk_robot/motor_sdk_robot_config.hpp"

namespace cerebellum {

// what the client did, for the backend's log and summary (the loop thread writes, a copy travels)
struct MotorSdkClientStatus {
  bool activated = false;          // the robot took our frames (err_flag bit 1 clear)
  bool stopped = false;            // a motor reported an error: damping frames until restart
  std::uint32_t error_motors = 0;  // bit i: motor i reported an error when the client stopped
  std::uint16_t err_flag = 0;      // the robot's newest motor_ctrl_state.err_flag
  bool link_lost = false;
  double link_silent_s = 0.0;  // at the last frame: since the older of the newest spi_data and state_estimator
  std::uint64_t link_losses = 0;     // times the link was lost
  std::uint64_t zero_frames = 0;     // all-zero frames sent while not activated
  std::uint64_t range_clamps = 0;    // frames with a value clamped into the vendor's ranges
  std::uint64_t jump_clamps = 0;     // frames with a position step clamped to 8 / 10 / 12 degrees
  std::uint64_t late_reports = 0;    // motor_ctrl_state with bit 0 (our frames came late)
  std::uint64_t jump_reports = 0;    // motor_ctrl_state with a position-jump bit (the robot clamped)
  std::uint64_t repeated_states = 0;  // spi_data or state_estimator equal to the one before: not fresh
  std::uint64_t jumped_states = 0;    // spi_data refused: an angle moved further than a joint can
  double last_jump_rad = 0.0;         // the largest angle step of the newest refused spi_data
};

// the largest step a joint's angle can make in dt_s: twice the no-load speed (a leg thrown by a
// fall may be driven past it), plus 5 degrees of encoder and timing slack
double joint_step_limit_rad(double dt_s);

class MotorSdkClient {
 public:
  explicit MotorSdkClient(const MotorSdkRobotConfig& config);

  // each message as it arrived, received_s on the link's clock (seconds, monotonic)
  void take_joints(const SpiJointState& joints, double received_s);
  void take_imu(const ImuSample& imu, double received_s);
  void take_err_flag(std::uint16_t err_flag);

  // the sensor frame, stamped robot_time_s, with the link judged over the receiver's listening
  // window (on the link's clock): the silence runs from the newer of the last message and
  // window.since_s to window.until_s, since a receiver that was not running cannot tell a silent
  // robot (a process or a machine paused, as a loaded host does, is not a lost link)
  SensorFrame frame(const ListeningWindow& window, double robot_time_s);
  // the frame to send (SDK convention) for the MC's command
  JointCommand command(const JointCommand& mc_command);

  const MotorSdkClientStatus& status() const { return status_; }

 private:
  MotorSdkRobotConfig config_;
  MotorSdkClientStatus status_;
  SensorFrame frame_;
  bool have_joints_ = false;
  bool have_imu_ = false;
  double joints_received_s_ = 0.0;
  double imu_received_s_ = 0.0;
  double lost_at_s_ = 0.0;  // when the link was last lost (link's clock)
};

}  // namespace cerebellum
