#include "safety/command_guard.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace cerebellum {
namespace {

RobotState valid_state() {
  RobotState state;
  state.valid = true;
  return state;
}

TEST(CommandLimits, DefaultsAreTheMotorCommandRangesOfTheReference) {
  // cyberdog2-lowlevel.md section 5: qd_des -12..12 rad/s, kp 0..200, kd 0..10, tau_des -12..12 Nm
  const CommandLimits limits;
  EXPECT_EQ(limits.kp_max, 200.0);
  EXPECT_EQ(limits.kd_max, 10.0);
  EXPECT_EQ(limits.qd_des_max_rad_s, 12.0);
  EXPECT_EQ(limits.tau_ff_max_nm, 12.0);
  EXPECT_EQ(limits.joint_limit_margin_rad, 0.04);
}

TEST(CommandGuard, InRangeCommandPassesUntouched) {
  JointCommand command;
  command.kp.fill(60.0);
  command.kd.fill(2.0);
  command.tau_ff.fill(1.0);
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) command.q_des[3 * leg + 2] = -1.2;
  const JointCommand original = command;
  const SafetyReport report = guard_command(valid_state(), command, GuardLimits{});
  EXPECT_EQ(report.flags, kGuardOk);
  EXPECT_EQ(command.q_des, original.q_des);
  EXPECT_EQ(command.kp, original.kp);
}

TEST(CommandGuard, ClampsEachRangeAndSaysWhich) {
  JointCommand command;
  command.kp.fill(250.0);
  command.kd.fill(-1.0);
  command.tau_ff.fill(20.0);
  command.qd_des.fill(-40.0);
  command.q_des.fill(-3.0);
  const SafetyReport report = guard_command(valid_state(), command, GuardLimits{});
  EXPECT_EQ(report.flags, kGuardClampedGain | kGuardClampedTorque | kGuardClampedVelocity | kGuardClampedPosition);
  EXPECT_EQ(command.kp[0], 200.0);
  EXPECT_EQ(command.kd[0], 0.0);
  EXPECT_EQ(command.tau_ff[0], 12.0);
  EXPECT_EQ(command.qd_des[0], -12.0);
  EXPECT_DOUBLE_EQ(command.q_des[0], -0.68 + 0.04);   // abad
  EXPECT_DOUBLE_EQ(command.q_des[1], -1.33 + 0.04);   // front hip
  EXPECT_DOUBLE_EQ(command.q_des[7], -0.98 + 0.04);   // rear hip
  EXPECT_DOUBLE_EQ(command.q_des[11], -2.53 + 0.04);  // knee
}

TEST(CommandGuard, NonFiniteValueAnywhereReplacesTheCommandWithDamping) {
  for (double bad : {std::nan(""), std::numeric_limits<double>::infinity()}) {
    JointCommand command;
    command.kp.fill(60.0);
    command.tau_ff[9] = bad;
    const SafetyReport report = guard_command(valid_state(), command, GuardLimits{});
    EXPECT_TRUE(report.replaced());
    EXPECT_TRUE(report.flags & kGuardNonFiniteCommand);
    for (std::size_t i = 0; i < kNumJoints; ++i) {
      EXPECT_EQ(command.kp[i], 0.0);
      EXPECT_EQ(command.tau_ff[i], 0.0);
      EXPECT_EQ(command.kd[i], 4.0);
    }
  }
}

TEST(CommandGuard, InvalidStateReplacesTheCommandWithDamping) {
  JointCommand command;
  command.kp.fill(60.0);
  const SafetyReport report = guard_command(RobotState{}, command, GuardLimits{});
  EXPECT_TRUE(report.flags & kGuardInvalidState);
  EXPECT_EQ(command.kp[0], 0.0);
}

}  // namespace
}  // namespace cerebellum

namespace cerebellum {
namespace {

JointCommand stiff_command() {
  JointCommand command;
  command.kp.fill(60.0);
  command.kd.fill(2.0);
  command.tau_ff.fill(3.0);
  return command;
}

TEST(CommandGuard, TheHealthProtectionDampsWhateverCommandCame) {
  JointCommand command = stiff_command();
  GuardLimits limits;
  limits.damping_kd = 4.0;
  const SafetyReport report = guard_command(valid_state(), command, limits, Protection::Damping);
  EXPECT_EQ(report.flags, kGuardHealthDamping);
  EXPECT_TRUE(report.replaced());
  for (std::size_t i = 0; i < kNumJoints; ++i) {
    EXPECT_EQ(command.kp[i], 0.0);
    EXPECT_EQ(command.kd[i], 4.0);
    EXPECT_EQ(command.tau_ff[i], 0.0);
  }
}

TEST(CommandGuard, AStoppedProtectionSwitchesTheMotorsOff) {
  JointCommand command = stiff_command();
  const SafetyReport report = guard_command(valid_state(), command, GuardLimits{}, Protection::Stopped);
  EXPECT_EQ(report.flags, kGuardHealthStopped);
  for (std::size_t i = 0; i < kNumJoints; ++i) {
    EXPECT_EQ(command.kp[i], 0.0);
    EXPECT_EQ(command.kd[i], 0.0);
    EXPECT_EQ(command.tau_ff[i], 0.0);
  }
}

}  // namespace
}  // namespace cerebellum
