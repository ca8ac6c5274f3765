// Value types exchanged between the stages of the control cycle.
#pragma once

#include <array>
#include <cstdint>

#include "core/joint_layout.hpp"
#include "core/motor_health.hpp"

namespace cerebellum {

// what the robot's sensors say at one instant (SDK joint convention)
// every driver in motor mode
inline JointArray<MotorDriverMode> all_motor_mode() {
  JointArray<MotorDriverMode> modes;
  modes.fill(MotorDriverMode::Motor);
  return modes;
}

struct SensorFrame {
  double time_s = 0.0;
  JointArray<double> q{};    // rad
  JointArray<double> qd{};   // rad/s
  JointArray<double> tau{};  // N m, torque the motor produced
  JointArray<double> temperature_c{};
  std::array<double, 4> imu_quat{1.0, 0.0, 0.0, 0.0};  // w, x, y, z, body to world
  std::array<double, 3> imu_gyro{};                    // rad/s, body frame
  std::array<double, 3> imu_accel{};                   // m/s^2, body frame, includes gravity
  double imu_temperature_c = 0.0;                      // the IMU chip's own sensor
  JointArray<std::uint32_t> motor_faults{};            // MotorFault bits per motor
  // each driver's mode; a backend that cannot tell reports motor mode (the healthy running state)
  JointArray<MotorDriverMode> driver_mode = all_motor_mode();
  BatteryReading battery;
};

// what the motors are told; each motor runs tau = tau_ff + kp (q_des - q) + kd (qd_des - qd)
struct JointCommand {
  JointArray<double> q_des{};
  JointArray<double> qd_des{};
  JointArray<double> kp{};
  JointArray<double> kd{};
  JointArray<double> tau_ff{};
};

// zero gains and torques: the motors are passive
inline JointCommand passive_command() { return JointCommand{}; }

}  // namespace cerebellum
