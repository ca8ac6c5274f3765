#include "safety/command_guard.hpp"

#include <algorithm>
#include <cmath>

#include "core/robot_model.hpp"

namespace cerebellum {
namespace {

bool command_is_finite(const JointCommand& command) {
  for (std::size_t i = 0; i < kNumJoints; ++i) {
    if (!std::isfinite(command.q_des[i]) || !std::isfinite(command.qd_des[i]) || !std::isfinite(command.kp[i]) ||
        !std::isfinite(command.kd[i]) || !std::isfinite(command.tau_ff[i])) {
      return false;
    }
  }
  return true;
}

// clamp value into [lower, upper]; raise flag when it had to move
void clamp_into(double& value, double lower, double upper, std::uint32_t flag, std::uint32_t& flags) {
  const double clamped = std::clamp(value, lower, upper);
  if (clamped != value) flags |= flag;
  value = clamped;
}

}  // namespace

JointCommand damping_command(const GuardLimits& limits) {
  JointCommand command;
  command.kd.fill(limits.damping_kd);
  return command;
}

SafetyReport guard_command(const RobotState& state, JointCommand& command, const GuardLimits& limits) {
  SafetyReport report;
  if (!state.valid) {
    report.flags |= kGuardInvalidState;
    command = damping_command(limits);
    return report;
  }
  if (!command_is_finite(command)) {
    report.flags |= kGuardNonFiniteCommand;
    command = damping_command(limits);
    return report;
  }
  for (std::size_t i = 0; i < kNumJoints; ++i) {
    const robot::JointRange range = robot::joint_range(i);
    clamp_into(command.kp[i], 0.0, limits.kp_max, kGuardClampedGain, report.flags);
    clamp_into(command.kd[i], 0.0, limits.kd_max, kGuardClampedGain, report.flags);
    clamp_into(command.tau_ff[i], -limits.tau_ff_max_nm, limits.tau_ff_max_nm, kGuardClampedTorque, report.flags);
    clamp_into(command.qd_des[i], -limits.qd_des_max_rad_s, limits.qd_des_max_rad_s, kGuardClampedVelocity,
               report.flags);
    // a position target only matters where kp acts on it
    if (command.kp[i] > 0.0) {
      clamp_into(command.q_des[i], range.lower + limits.joint_limit_margin_rad,
                 range.upper - limits.joint_limit_margin_rad, kGuardClampedPosition, report.flags);
    }
  }
  return report;
}

}  // namespace cerebellum
