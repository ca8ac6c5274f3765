#include "safety/command_clamp.hpp"

#include <algorithm>

#include "core/robot_model.hpp"

namespace cerebellum {
bool clamp_into(double& value, double lower, double upper) {
  const double clamped = std::clamp(value, lower, upper);
  const bool moved = clamped != value;
  value = clamped;
  return moved;
}

CommandClampCount clamp_command(JointCommand& command, const CommandLimits& limits, double kp_acts_above) {
  CommandClampCount count;
  for (std::size_t i = 0; i < kNumJoints; ++i) {
    const bool kp_moved = clamp_into(command.kp[i], 0.0, limits.kp_max);
    const bool kd_moved = clamp_into(command.kd[i], 0.0, limits.kd_max);
    count.gains += (kp_moved || kd_moved) ? 1 : 0;
    count.velocities += clamp_into(command.qd_des[i], -limits.qd_des_max_rad_s, limits.qd_des_max_rad_s);
    count.torques += clamp_into(command.tau_ff[i], -limits.tau_ff_max_nm, limits.tau_ff_max_nm);
    if (command.kp[i] > kp_acts_above) {
      const robot::JointRange range = robot::joint_range(i);
      count.positions += clamp_into(command.q_des[i], range.lower + limits.joint_limit_margin_rad,
                                    range.upper - limits.joint_limit_margin_rad);
    }
  }
  return count;
}

}  // namespace cerebellum
