// What the estimator believes about the robot; the only robot state controllers see.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <array>

#include "core/ground_plane.hpp"
#include "core/specific_force.hpp"
#include "core/types.hpp"

namespace cerebellum {

struct RobotState {
  double time_s = 0.0;
  // joints, SDK convention
  JointArray<double> q{};
  JointArray<double> qd{};
  JointArray<double> tau{};
  JointArray<double> temperature_c{};
  double imu_temperature_c = 0.0;  // the IMU chip's own sensor, as it reads
  JointArray<std::uint32_t> motor_faults{};                    // MotorFault bits as the drivers report them
  JointArray<MotorDriverMode> driver_mode = all_motor_mode();  // as the drivers report it
  BatteryReading battery;
  // trunk
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();  // body to world
  Eigen::Vector3d rpy = Eigen::Vector3d::Zero();                    // roll, pitch, yaw (ZYX)
  Eigen::Vector3d omega_body = Eigen::Vector3d::Zero();
  Eigen::Vector3d omega_world = Eigen::Vector3d::Zero();
  // the IMU's accelerometer as it reads: the specific force (acceleration minus gravity's), body
  // frame, m/s^2: about (0, 0, +9.81) standing level, zero in free fall (core/specific_force.hpp);
  // until the first frame, at rest in the default (level) orientation
  Eigen::Vector3d specific_force_body = specific_force_at_rest_world();
  // the IMU's acceleration, world frame, gravity's part taken out (acceleration_from_specific_force):
  // about zero at rest, -9.81 on z in free fall; what the filter, the safety checks and the
  // controllers use
  Eigen::Vector3d accel_world = Eigen::Vector3d::Zero();
  Eigen::Vector3d position_world = Eigen::Vector3d::Zero();
  Eigen::Vector3d velocity_world = Eigen::Vector3d::Zero();
  Eigen::Vector3d velocity_body = Eigen::Vector3d::Zero();
  // trunk height above the ground under the stance feet (m)
  double height_m = 0.0;
  // the ground plane through the recently planted feet (world)
  GroundPlane ground;
  // per leg: foot position in the body frame and contact probability 0..1
  std::array<Eigen::Vector3d, kNumLegs> foot_position_body{};
  std::array<double, kNumLegs> contact{};
  bool valid = false;  // false until the first good sensor frame, and after NaN input
};

}  // namespace cerebellum
