#include "safety/command_guard.hpp"

#include <algorithm>

#include "core/robot_model.hpp"
#include "safety/command_finite.hpp"
#include "safety/damping_command.hpp"

namespace cerebellum {
namespace {

// clamp value into [lower, upper]; raise flag when it had to move
void clamp_into(double& value, double lower, double upper, std::uint32_t flag, std::uint32_t& flags) {
  const double clamped = std::clamp(value, lower, upper);
  if (clamped != value) flags |= flag;
  value = clamped;
}

}  // namespace

SafetyReport guard_command(const RobotState& state, JointCommand& command, const GuardLimits& limits) {
  SafetyReport report;
  if (!state.valid) {
    report.flags |= kGuardInvalidState;
    command = damping_command(limits.damping_kd);
    return report;
  }
  if (!command_is_finite(command)) {
    report.flags |= kGuardNonFiniteCommand;
    command = damping_command(limits.damping_kd);
    return report;
  }
  const CommandLimits& l = limits.command;
  for (std::size_t i = 0; i < kNumJoints; ++i) {
    const robot::JointRange range = robot::joint_range(i);
    clamp_into(command.kp[i], 0.0, l.kp_max, kGuardClampedGain, report.flags);
    clamp_into(command.kd[i], 0.0, l.kd_max, kGuardClampedGain, report.flags);
    clamp_into(command.tau_ff[i], -l.tau_ff_max_nm, l.tau_ff_max_nm, kGuardClampedTorque, report.flags);
    clamp_into(command.qd_des[i], -l.qd_des_max_rad_s, l.qd_des_max_rad_s, kGuardClampedVelocity, report.flags);
    // a position target only matters where kp acts on it
    if (command.kp[i] > 0.0) {
      clamp_into(command.q_des[i], range.lower + l.joint_limit_margin_rad, range.upper - l.joint_limit_margin_rad,
                 kGuardClampedPosition, report.flags);
    }
  }
  return report;
}

}  // namespace cerebellum
