// The last stage of every cycle: a pure function that keeps the joint command inside the
// robot's limits and replaces it with damping when it (or the state) cannot be trusted.
#pragma once

#include <cstdint>

#include "core/robot_state.hpp"
#include "core/types.hpp"

namespace cerebellum {

struct GuardLimits {
  double kp_max = 200.0;
  double kd_max = 10.0;
  double tau_ff_max_nm = 12.0;
  double qd_des_max_rad_s = 12.0;
  double joint_limit_margin_rad = 0.04;  // q_des kept this far inside the joint range
  double damping_kd = 4.0;               // kd of the replacement command
};

// what the guard did this cycle, one bit per cause
enum GuardFlag : std::uint32_t {
  kGuardOk = 0,
  kGuardClampedGain = 1u << 0,
  kGuardClampedTorque = 1u << 1,
  kGuardClampedVelocity = 1u << 2,
  kGuardClampedPosition = 1u << 3,
  kGuardNonFiniteCommand = 1u << 4,  // command replaced by damping
  kGuardInvalidState = 1u << 5,      // state not trusted: command replaced by damping
};

struct SafetyReport {
  std::uint32_t flags = kGuardOk;
  bool replaced() const { return (flags & (kGuardNonFiniteCommand | kGuardInvalidState)) != 0; }
};

// joint damping: kp 0, tau 0, kd = damping_kd; the robot sinks slowly
JointCommand damping_command(const GuardLimits& limits);

SafetyReport guard_command(const RobotState& state, JointCommand& command, const GuardLimits& limits);

}  // namespace cerebellum
