// Joint order and sign conventions of cerebellum, defined once for the whole project.
#pragma once

#include <array>
#include <cstddef>

namespace cerebellum {

inline constexpr std::size_t kNumLegs = 4;
inline constexpr std::size_t kJointsPerLeg = 3;
inline constexpr std::size_t kNumJoints = kNumLegs * kJointsPerLeg;

// legs in this order everywhere: front right, front left, rear right, rear left
enum class Leg : std::size_t { FR = 0, FL = 1, RR = 2, RL = 3 };
// their names, in that order (messages, model element names)
inline constexpr std::array<const char*, kNumLegs> kLegNames{"FR", "FL", "RR", "RL"};
// joints of a leg: abad (about x), hip (about y), knee (about y)
enum class Joint : std::size_t { Abad = 0, Hip = 1, Knee = 2 };
inline constexpr std::array<const char*, kJointsPerLeg> kJointNames{"abad", "hip", "knee"};

template <typename T>
using JointArray = std::array<T, kNumJoints>;

constexpr std::size_t joint_index(std::size_t leg, std::size_t joint) { return kJointsPerLeg * leg + joint; }
constexpr std::size_t joint_index(Leg leg, Joint joint) {
  return joint_index(static_cast<std::size_t>(leg), static_cast<std::size_t>(joint));
}

// +1 for left legs, -1 for right legs: the sign of the hip's y offset
constexpr double leg_side_sign(std::size_t leg) { return (leg % 2 == 1) ? 1.0 : -1.0; }
constexpr bool is_front_leg(std::size_t leg) { return leg < 2; }

// Two joint conventions exist on the CyberDog2:
// - SDK convention (URDF, the seeds' joint table, the simulator model, everything inside
//   cerebellum): zero = leg straight down, positive = right-hand rule about the joint axis.
// - wire convention (the MC's internal one, used on motor_ctrl, spi_data, leg_control_data):
//   hip and knee negated, i.e. wire = sdk * {+1, -1, -1} per leg.
constexpr double wire_sign(std::size_t joint_in_leg) { return joint_in_leg == 0 ? 1.0 : -1.0; }

template <typename T>
constexpr JointArray<T> sdk_to_wire(const JointArray<T>& sdk) {
  JointArray<T> wire{};
  for (std::size_t i = 0; i < kNumJoints; ++i) wire[i] = static_cast<T>(sdk[i] * wire_sign(i % kJointsPerLeg));
  return wire;
}
// the flip is its own inverse
template <typename T>
constexpr JointArray<T> wire_to_sdk(const JointArray<T>& wire) {
  return sdk_to_wire(wire);
}

}  // namespace cerebellum
