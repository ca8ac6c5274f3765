#include "safety/command_guard.hpp"

#include "safety/command_clamp.hpp"
#include "safety/command_finite.hpp"
#include "safety/damping_command.hpp"

namespace cerebellum {

SafetyReport guard_command(const RobotState& state, JointCommand& command, const GuardLimits& limits,
                           Protection protection) {
  SafetyReport report;
  if (protection == Protection::Stopped) {
    report.flags |= kGuardHealthStopped;
    command = passive_command();
    return report;
  }
  if (protection == Protection::Damping) {
    report.flags |= kGuardHealthDamping;
    command = damping_command(limits.damping_kd);
    return report;
  }
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
  const CommandClampCount clamped = clamp_command(command, limits.command);
  if (clamped.gains > 0) report.flags |= kGuardClampedGain;
  if (clamped.torques > 0) report.flags |= kGuardClampedTorque;
  if (clamped.velocities > 0) report.flags |= kGuardClampedVelocity;
  if (clamped.positions > 0) report.flags |= kGuardClampedPosition;
  return report;
}

}  // namespace cerebellum
