// A CyberDog2 lying down (robot::kLyingPose on every leg), as a real robot's link reports it after
// power-on: what the tests of the robot link and the robot backends read.
#pragma once

#include "core/joint_layout.hpp"
#include "core/robot_model.hpp"
#include "core/robot_readings.hpp"
#include "io/robot_link/listening_window.hpp"

namespace cerebellum {

inline JointArray<double> lying_joint_angles() {
  JointArray<double> q{};
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
    for (std::size_t joint = 0; joint < kJointsPerLeg; ++joint) q[joint_index(leg, joint)] = robot::kLyingPose[joint];
  }
  return q;
}

// a healthy robot lying still
inline JointReading lying_joints() {
  JointReading joints;
  joints.q = lying_joint_angles();
  return joints;
}

// a receiver that has listened without a pause since since_s, its newest step at until_s
inline ListeningWindow listened(double until_s, double since_s = 0.0) { return ListeningWindow{since_s, until_s}; }

// a live robot's state at received_s: its values change with time, as a real one's noise makes
// them (two equal states in a row are a stuck sender, not news)
inline JointReading live_joints(double received_s) {
  JointReading joints = lying_joints();
  joints.qd[0] = received_s;
  return joints;
}
inline ImuReading live_imu(double received_s) {
  return ImuReading{{1.0, 0.0, 0.0, 0.0}, {0.0, 0.0, received_s}, {0.0, 0.0, 9.81}};
}

}  // namespace cerebellum
