// The rules the MC applies to motor SDK frames (cyberdog2-lowlevel.md section 5), as numbers.
#pragma once

#include <array>
#include <cstdint>

#include "core/robot_model.hpp"
#include "safety/command_limits.hpp"

namespace cerebellum {

// motor_ctrl_state.err_flag bits
enum MotorSdkErrFlag : std::uint16_t {
  kMotorSdkCommandLate = 1u << 0,  // warning: more than 10 ms since the last frame, command decays
  kMotorSdkCommandLost = 1u << 1,  // error: more than 500 ms (or just entered): damping, lie down
  kMotorSdkAbadJump = 1u << 2,     // warning: abad q_des step clamped
  kMotorSdkHipJump = 1u << 3,      // warning: hip q_des step clamped
  kMotorSdkKneeJump = 1u << 4,     // warning: knee q_des step clamped
};

struct MotorSdkParameters {
  // communication timing (robot time)
  double late_after_s = 0.010;      // bit0 beyond this gap; commands are scaled by late_after_s / gap
  double lost_after_s = 0.500;      // bit1 beyond this gap
  double lie_before_clear_s = 2.0;  // bit1 stays at least this long before zero frames clear it
  // while bit1 is set: joint damping for a while, then limp (the firmware's variant)
  double lost_damping_kd = robot::kDampingKd;
  double lost_damping_duration_s = 2.5;
  // |kp|, |kd|, |tau_des| at or below this everywhere make an all-zero (activation) frame
  double zero_tolerance = 0.001;
  // position jump clamps per joint (abad, hip, knee), rad; switched by the user parameter file
  bool position_mutation_limit = true;
  std::array<double, 3> max_position_step_rad{robot::deg(8.0), robot::deg(10.0), robot::deg(12.0)};
  // accepted ranges; values outside are clamped and counted
  CommandLimits limits;
};

}  // namespace cerebellum
