// Pure functions that turn one received motor SDK frame (SDK joint convention) into what the
// motors may execute: range clamps, position jump clamps, the late-frame decay.
#pragma once

#include <cstdint>

#include "core/types.hpp"
#include "lowlevel/motor_sdk/motor_sdk_parameters.hpp"
#include "safety/command_clamp.hpp"

namespace cerebellum {

// how many joints had each quantity clamped in one frame
using RangeClampCount = CommandClampCount;

struct JumpClampResult {
  std::uint16_t err_bits = 0;  // kMotorSdkAbadJump / HipJump / KneeJump
  std::uint32_t joints = 0;    // joints whose step was clamped
};

// the shared clamp (safety/command_clamp.hpp) into parameters.limits; q_des only where
// kp > zero_tolerance (elsewhere the position does not act)
RangeClampCount clamp_to_ranges(JointCommand& frame, const MotorSdkParameters& parameters);

// limits each acting joint's q_des to measured_q +- max_position_step_rad of its joint type (the
// firmware measures the jump against the joint's angle, not against the previous frame)
JumpClampResult clamp_position_jumps(JointCommand& frame, const JointArray<double>& measured_q,
                                     const MotorSdkParameters& parameters);

// the activation frame: |kp|, |kd| and |tau_des| at or below tolerance on every joint
bool is_all_zero_frame(const JointCommand& frame, double tolerance);

// a frame gap_s old (gap_s > late_after_s): qd_des and tau_des scaled by late_after_s / gap_s and
// the position error to the measured angle scaled the same way, so the target decays towards
// where the joint is instead of holding a stale stiff target
void decay_late_command(JointCommand& command, const JointArray<double>& q_measured, double gap_s,
                        const MotorSdkParameters& parameters);

}  // namespace cerebellum
