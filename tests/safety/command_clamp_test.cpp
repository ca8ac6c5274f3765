// The shared clamp against a field-by-field recomputation on random commands.
#include "safety/command_clamp.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "core/robot_model.hpp"

namespace cerebellum {
namespace {

TEST(CommandClamp, MatchesAFieldByFieldClampAndCountsTheJointsItMoved) {
  std::mt19937 rng(12);
  std::uniform_real_distribution<double> wide(-1.0, 1.0);
  const CommandLimits limits;
  for (int trial = 0; trial < 200; ++trial) {
    JointCommand command;
    for (std::size_t i = 0; i < kNumJoints; ++i) {
      command.q_des[i] = 4.0 * wide(rng);
      command.qd_des[i] = 20.0 * wide(rng);
      command.kp[i] = 300.0 * wide(rng);
      command.kd[i] = 15.0 * wide(rng);
      command.tau_ff[i] = 20.0 * wide(rng);
    }
    const JointCommand before = command;
    const double kp_acts_above = trial % 2 == 0 ? 0.0 : 0.001;
    const CommandClampCount count = clamp_command(command, limits, kp_acts_above);
    CommandClampCount expected;
    for (std::size_t i = 0; i < kNumJoints; ++i) {
      const double kp = std::min(std::max(before.kp[i], 0.0), limits.kp_max);
      const double kd = std::min(std::max(before.kd[i], 0.0), limits.kd_max);
      const double qd = std::min(std::max(before.qd_des[i], -limits.qd_des_max_rad_s), limits.qd_des_max_rad_s);
      const double tau = std::min(std::max(before.tau_ff[i], -limits.tau_ff_max_nm), limits.tau_ff_max_nm);
      const robot::JointRange range = robot::joint_range(i);
      const double low = range.lower + limits.joint_limit_margin_rad;
      const double high = range.upper - limits.joint_limit_margin_rad;
      const double q = kp > kp_acts_above ? std::min(std::max(before.q_des[i], low), high) : before.q_des[i];
      EXPECT_EQ(command.kp[i], kp);
      EXPECT_EQ(command.kd[i], kd);
      EXPECT_EQ(command.qd_des[i], qd);
      EXPECT_EQ(command.tau_ff[i], tau);
      EXPECT_EQ(command.q_des[i], q);
      expected.gains += (kp != before.kp[i] || kd != before.kd[i]) ? 1 : 0;
      expected.velocities += qd != before.qd_des[i] ? 1 : 0;
      expected.torques += tau != before.tau_ff[i] ? 1 : 0;
      expected.positions += q != before.q_des[i] ? 1 : 0;
    }
    EXPECT_EQ(count.gains, expected.gains);
    EXPECT_EQ(count.velocities, expected.velocities);
    EXPECT_EQ(count.torques, expected.torques);
    EXPECT_EQ(count.positions, expected.positions);
  }
}

}  // namespace
}  // namespace cerebellum
