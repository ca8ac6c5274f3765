// What an AlienGo HighCmd asks, in our own types (the wire struct stays in aliengo_wire.cpp), and
// what the MC answers in a HighState.
#pragma once

#include <array>
#include <cstdint>

#include <Eigen/Core>

#include "core/joint_layout.hpp"

namespace cerebellum {

// HighCmd.mode
enum class AlienGoMode : int {
  Idle = 0,
  ForceStand = 1,
  WalkVelocity = 2,
  WalkPosition = 3,
  WalkPath = 4,  // reserved by the vendor: answered "not supported"
  StandDown = 5,
  StandUp = 6,
  Damping = 7,
  Recovery = 8,
};
inline constexpr int kAlienGoModeCount = 9;

// HighCmd.gaitType
enum class AlienGoGait : int { Trot = 0, TrotRunning = 1, Stairs = 2 };

struct AlienGoCommand {
  int mode = 0;
  int gait_type = 0;
  int speed_level = 0;
  float foot_raise_m = 0.0f;        // added to the default swing height
  float body_height_m = 0.0f;       // added to the default body height
  std::array<float, 2> position{};  // mode 3 target, the frame fixed when sport mode started
  std::array<float, 3> rpy{};
  std::array<float, 2> velocity{};  // forward, side (body frame)
  float yaw_speed = 0.0f;
};

// HighState: the estimator's view of the robot, in the vendor's frames and units
struct AlienGoFeedback {
  int mode = 0;
  Eigen::Vector4d quaternion_wxyz{1, 0, 0, 0};
  Eigen::Vector3d gyroscope = Eigen::Vector3d::Zero();      // body, rad/s
  Eigen::Vector3d accelerometer = Eigen::Vector3d::Zero();  // body, specific force, m/s^2
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
