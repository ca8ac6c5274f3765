// What the MC answers in an AlienGo HighState, in our own types (the wire struct stays in
// aliengo_wire.cpp).
#pragma once

#include <array>

#include <Eigen/Core>

#include "core/joint_layout.hpp"

namespace cerebellum {

// HighState: the estimator's view of the robot, in the vendor's frames and units
struct AlienGoFeedback {
  int mode = 0;
  Eigen::Vector4d quaternion_wxyz{1, 0, 0, 0};
  Eigen::Vector3d gyroscope = Eigen::Vector3d::Zero();      // body, rad/s
  Eigen::Vector3d accelerometer = Eigen::Vector3d::Zero();  // body, specific force (gravity included), m/s^2
  Eigen::Vector3d rpy = Eigen::Vector3d::Zero();
  int temperature_c = 0;
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  // odometry, world
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();  // body frame
  double yaw_speed = 0.0;
  std::array<Eigen::Vector3d, kNumLegs> foot_position{};  // body frame, FR FL RR RL
  std::array<Eigen::Vector3d, kNumLegs> foot_velocity{};
  std::array<int, kNumLegs> foot_force{};  // 0.1 N
};

}  // namespace cerebellum
