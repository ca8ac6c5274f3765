// Keeping a joint command inside its ranges, the one clamp the guard and the motor SDK's frame
// rules share: each counts what it had to move, and reports it its own way.
#pragma once

#include <cstdint>

#include "core/types.hpp"
#include "safety/command_limits.hpp"

namespace cerebellum {

// how many joints had each quantity clamped
struct CommandClampCount {
  std::uint32_t gains = 0;       // kp or kd
  std::uint32_t velocities = 0;  // qd_des
  std::uint32_t torques = 0;     // tau_ff
  std::uint32_t positions = 0;   // q_des outside the joint range less the margin (only where kp acts)
};

// kp into [0, kp_max], kd into [0, kd_max], qd_des and tau_ff symmetric; q_des kept
// joint_limit_margin_rad inside the joint range where the clamped kp is above kp_acts_above
// (elsewhere the position target does not act)
CommandClampCount clamp_command(JointCommand& command, const CommandLimits& limits, double kp_acts_above = 0.0);

// clamp one value into [lower, upper]; true when it had to move (the low-level rules count them)
bool clamp_into(double& value, double lower, double upper);

}  // namespace cerebellum
