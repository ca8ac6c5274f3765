// The one damping command: only kd acts, so the torque the motor law gives is -kd qd.
#include "safety/damping_command.hpp"

#include <gtest/gtest.h>

namespace cerebellum {
namespace {

TEST(DampingCommand, TheMotorLawGivesMinusKdTimesTheJointSpeed) {
  JointArray<double> q{};
  for (std::size_t i = 0; i < kNumJoints; ++i) q[i] = 0.1 * static_cast<double>(i) - 0.5;
  const JointCommand command = damping_command(4.0, q);
  for (std::size_t i = 0; i < kNumJoints; ++i) {
    // tau = tau_ff + kp (q_des - q) + kd (qd_des - qd) at any q and qd
    const double q_now = 0.3, qd_now = -1.7;
    const double tau =
        command.tau_ff[i] + command.kp[i] * (command.q_des[i] - q_now) + command.kd[i] * (command.qd_des[i] - qd_now);
    EXPECT_DOUBLE_EQ(tau, -4.0 * qd_now) << i;
    EXPECT_EQ(command.q_des[i], q[i]) << i;
  }
}

TEST(DampingCommand, HoldsZeroTargetsWhenNoAnglesAreGiven) {
  const JointCommand command = damping_command(2.5);
  for (std::size_t i = 0; i < kNumJoints; ++i) {
    EXPECT_EQ(command.q_des[i], 0.0);
    EXPECT_EQ(command.kd[i], 2.5);
  }
}

}  // namespace
}  // namespace cerebellum
