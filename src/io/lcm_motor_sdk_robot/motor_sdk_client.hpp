// The rules of a motor SDK client, as the vendor's client library keeps them, on the MC's types and
// without sockets (the backend's thread decodes the wire, the loop thread applies these):
// - activation: all-zero frames until the robot reports motor_ctrl_state without err_flag bit 1,
//   and again whenever bit 1 comes back (the robot is then damping and waits for zero frames);
// - a motor reporting an error: stop commanding at once (damping frames, latched until restart);
// - the vendor's command ranges and position-jump steps applied before sending, counted;
// - what every robot's state must pass (the link watch, states that repeat or jump, the motor
//   error): io/robot_link/robot_state_watch.hpp, on spi_data (joints) and state_estimator (IMU).
#pragma once

#include <cstdint>

#include "core/robot_readings.hpp"
#include "core/types.hpp"
#include "io/lcm_motor_sdk_robot/motor_sdk_robot_config.hpp"
#include "io/robot_link/robot_state_watch.hpp"

namespace cerebellum {

// what the client did, for the backend's log and summary (the loop thread writes, a copy travels):
// the state watch's figures and the motor SDK's own
struct MotorSdkClientStatus : RobotLinkStatus {
  bool activated = false;          // the robot took our frames (err_flag bit 1 clear)
  std::uint16_t err_flag = 0;      // the robot's newest motor_ctrl_state.err_flag
  std::uint64_t zero_frames = 0;     // all-zero frames sent while not activated
  std::uint64_t range_clamps = 0;    // frames with a value clamped into the vendor's ranges
  std::uint64_t jump_clamps = 0;     // frames with a position step clamped to 8 / 10 / 12 degrees
  std::uint64_t late_reports = 0;    // motor_ctrl_state with bit 0 (our frames came late)
  std::uint64_t jump_reports = 0;    // motor_ctrl_state with a position-jump bit (the robot clamped)
};

class MotorSdkClient {
 public:
  explicit MotorSdkClient(const MotorSdkRobotConfig& config);

  // each message as it arrived, received_s on the link's clock (seconds, monotonic)
  void take_joints(const JointReading& joints, double received_s);
  void take_imu(const ImuReading& imu, double received_s);
  void take_err_flag(std::uint16_t err_flag);

  // the sensor frame, stamped robot_time_s, the link judged over the receiver's listening window
  // (RobotStateWatch::frame)
  SensorFrame frame(const ListeningWindow& window, double robot_time_s);
  // the frame to send (SDK convention) for the MC's command
  JointCommand command(const JointCommand& mc_command);

  const MotorSdkClientStatus& status() const { return status_; }

 private:
  void take_watch_status() { static_cast<RobotLinkStatus&>(status_) = watch_.status(); }

  MotorSdkRobotConfig config_;
  RobotStateWatch watch_;
  MotorSdkClientStatus status_;
};

}  // namespace cerebellum
