// The joint angles of a CyberDog2 lying down (robot::kLyingPose on every leg): the robot the motor
// SDK robot backend's tests read, as after power-on.
#pragma once

#include "core/joint_layout.hpp"
#include "core/robot_model.hpp"

namespace cerebellum {

inline JointArray<double> lying_joint_angles() {
  JointArray<double> q{};
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
    for (std::size_t joint = 0; joint < kJointsPerLeg; ++joint) q[joint_index(leg, joint)] = robot::kLyingPose[joint];
  }
  return q;
}

}  // namespace cerebellum
