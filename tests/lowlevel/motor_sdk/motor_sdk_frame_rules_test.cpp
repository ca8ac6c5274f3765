// The per-frame rules: range clamps, jump clamps, the activation frame test, the late decay.
#include "lowlevel/motor_sdk/motor_sdk_frame_rules.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace cerebellum {
namespace {

constexpr double kPi = 3.14159265358979323846;
double degrees(double d) { return d * kPi / 180.0; }

JointCommand stiff_frame(double q_des, double kp) {
  JointCommand frame;
  frame.q_des.fill(q_des);
  frame.kp.fill(kp);
  return frame;
}

TEST(MotorSdkFrameRules, ClampsEachRangeAndCountsTheJoints) {
  MotorSdkParameters parameters;
  JointCommand frame;
  frame.kp[0] = 250.0;
  frame.kd[1] = -1.0;
  frame.kd[4] = 11.0;
  frame.qd_des[2] = 20.0;
  frame.tau_ff[3] = -15.0;
  frame.tau_ff[5] = 11.9;  // inside: untouched
  // knee 2 (index 8) far above its upper limit -0.52, with stiffness: pulled to -0.52 - 0.04
  frame.kp[8] = 10.0;
  frame.q_des[8] = 0.0;
  // knee 3 (index 11) equally far out, but kp 0: its position does not act and stays
  frame.q_des[11] = 0.0;

  const RangeClampCount count = clamp_to_ranges(frame, parameters);
  EXPECT_EQ(frame.kp[0], 200.0);
  EXPECT_EQ(frame.kd[1], 0.0);
  EXPECT_EQ(frame.kd[4], 10.0);
  EXPECT_EQ(frame.qd_des[2], 12.0);
  EXPECT_EQ(frame.tau_ff[3], -12.0);
  EXPECT_EQ(frame.tau_ff[5], 11.9);
  EXPECT_NEAR(frame.q_des[8], -0.56, 1e-12);
  EXPECT_EQ(frame.q_des[11], 0.0);
  EXPECT_EQ(count.gains, 3u);
  EXPECT_EQ(count.velocities, 1u);
  EXPECT_EQ(count.torques, 1u);
  EXPECT_EQ(count.positions, 1u);
}

TEST(MotorSdkFrameRules, FrontAndRearHipsHaveTheirOwnLimits) {
  MotorSdkParameters parameters;
  JointCommand frame = stiff_frame(3.5, 10.0);
  clamp_to_ranges(frame, parameters);
  EXPECT_NEAR(frame.q_des[1], 2.79 - 0.04, 1e-12);  // FR hip
  EXPECT_NEAR(frame.q_des[7], 3.14 - 0.04, 1e-12);  // RR hip
  EXPECT_NEAR(frame.q_des[0], 0.68 - 0.04, 1e-12);  // FR abad
}

TEST(MotorSdkFrameRules, JumpClampLimitsEachJointTypeToItsStep) {
  MotorSdkParameters parameters;
  JointArray<double> reference{};
  reference.fill(-1.0);
  JointCommand frame = stiff_frame(-1.0, 20.0);
  frame.q_des[0] = -1.0 + degrees(5.0);   // abad, within 8 deg
  frame.q_des[3] = -1.0 - degrees(9.0);   // abad, beyond 8 deg
  frame.q_des[4] = -1.0 - degrees(11.0);  // hip, beyond 10 deg
  frame.q_des[8] = -1.0 + degrees(30.0);  // knee, beyond 12 deg
  const JumpClampResult result = clamp_position_jumps(frame, reference, parameters);
  EXPECT_NEAR(frame.q_des[0], -1.0 + degrees(5.0), 1e-12);
  EXPECT_NEAR(frame.q_des[3], -1.0 - degrees(8.0), 1e-12);
  EXPECT_NEAR(frame.q_des[4], -1.0 - degrees(10.0), 1e-12);
  EXPECT_NEAR(frame.q_des[8], -1.0 + degrees(12.0), 1e-12);
  EXPECT_EQ(result.err_bits, kMotorSdkAbadJump | kMotorSdkHipJump | kMotorSdkKneeJump);
  EXPECT_EQ(result.joints, 3u);
}

TEST(MotorSdkFrameRules, JumpClampIgnoresJointsWithoutStiffness) {
  MotorSdkParameters parameters;
  JointArray<double> reference{};
  JointCommand frame = stiff_frame(1.0, 0.0);
  const JumpClampResult result = clamp_position_jumps(frame, reference, parameters);
  EXPECT_EQ(result.err_bits, 0);
  EXPECT_EQ(frame.q_des[2], 1.0);
}

TEST(MotorSdkFrameRules, AllZeroFrameIgnoresPositionsAndHonoursTheTolerance) {
  JointCommand frame;
  frame.q_des.fill(0.7);
  frame.qd_des.fill(2.0);
  EXPECT_TRUE(is_all_zero_frame(frame, 0.001));
  frame.kp[5] = 0.001;
  frame.kd[6] = -0.001;
  frame.tau_ff[7] = 0.001;
  EXPECT_TRUE(is_all_zero_frame(frame, 0.001));
  frame.tau_ff[7] = -0.0011;
  EXPECT_FALSE(is_all_zero_frame(frame, 0.001));
}

TEST(MotorSdkFrameRules, LateCommandDecaysByTenMillisecondsOverTheGap) {
  MotorSdkParameters parameters;
  JointCommand command = stiff_frame(1.0, 30.0);
  command.qd_des.fill(4.0);
  command.tau_ff.fill(2.0);
  command.kd.fill(1.5);
  JointArray<double> measured{};
  measured.fill(0.5);
  decay_late_command(command, measured, 0.040, parameters);  // factor 0.25
  for (std::size_t i = 0; i < kNumJoints; ++i) {
    EXPECT_DOUBLE_EQ(command.qd_des[i], 1.0);
    EXPECT_DOUBLE_EQ(command.tau_ff[i], 0.5);
    EXPECT_DOUBLE_EQ(command.q_des[i], 0.625);  // a quarter of the way from 0.5 to 1.0
    EXPECT_DOUBLE_EQ(command.kp[i], 30.0);
    EXPECT_DOUBLE_EQ(command.kd[i], 1.5);
  }
}

}  // namespace
}  // namespace cerebellum
