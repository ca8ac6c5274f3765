#include "lowlevel/motor_sdk/motor_sdk_frame_rules.hpp"

#include <algorithm>
#include <cmath>

#include "core/robot_model.hpp"
#include "safety/command_clamp.hpp"

namespace cerebellum {
RangeClampCount clamp_to_ranges(JointCommand& frame, const MotorSdkParameters& parameters) {
  return clamp_command(frame, parameters.limits, parameters.zero_tolerance);
}

JumpClampResult clamp_position_jumps(JointCommand& frame, const JointArray<double>& measured_q,
                                     const MotorSdkParameters& parameters) {
  static constexpr std::uint16_t kJumpBit[kJointsPerLeg] = {kMotorSdkAbadJump, kMotorSdkHipJump, kMotorSdkKneeJump};
  JumpClampResult result;
  for (std::size_t i = 0; i < kNumJoints; ++i) {
    if (frame.kp[i] <= parameters.zero_tolerance) continue;
    const std::size_t joint = i % kJointsPerLeg;
    const double max_step = parameters.max_position_step_rad[joint];
    if (clamp_into(frame.q_des[i], measured_q[i] - max_step, measured_q[i] + max_step)) {
      result.err_bits |= kJumpBit[joint];
      ++result.joints;
    }
  }
  return result;
}

bool is_all_zero_frame(const JointCommand& frame, double tolerance) {
  for (std::size_t i = 0; i < kNumJoints; ++i) {
    if (std::abs(frame.kp[i]) > tolerance || std::abs(frame.kd[i]) > tolerance ||
        std::abs(frame.tau_ff[i]) > tolerance) {
      return false;
    }
  }
  return true;
}

void decay_late_command(JointCommand& command, const JointArray<double>& q_measured, double gap_s,
                        const MotorSdkParameters& parameters) {
  const double factor = parameters.late_after_s / gap_s;
  for (std::size_t i = 0; i < kNumJoints; ++i) {
    command.qd_des[i] *= factor;
    command.tau_ff[i] *= factor;
    command.q_des[i] = q_measured[i] + factor * (command.q_des[i] - q_measured[i]);
  }
}

}  // namespace cerebellum
