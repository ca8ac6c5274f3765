// Playing a flip file: the plan between its knots, each pair's two legs alike, the abad joints
// straight, and the landing pose held once the plan has ended.
#include <gtest/gtest.h>

#include "control/jump/flip_player.hpp"
#include "core/joint_layout.hpp"

namespace cerebellum {
namespace {

FlipTrajectory two_knots() {
  FlipTrajectory t;
  t.samples.push_back({0.0, 0, {0.0, 0.26, 0.0}, {0.8, -1.2, 0.7, -1.1}, {0.0, 0.0, 0.0, 0.0}, {1.0, 2.0, 3.0, 4.0}});
  t.samples.push_back({0.1, 2, {0.0, 0.3, -1.0}, {1.0, -1.0, 0.9, -1.3}, {2.0, 4.0, 6.0, 8.0}, {3.0, 4.0, 5.0, 6.0}});
  return t;
}

TEST(FlipPlayer, BetweenKnotsThePlanIsInterpolatedAndEachPairsLegsMoveAlike) {
  const JointCommand c = flip_play_command(two_knots(), 0.05);
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
    const std::size_t j = leg * kJointsPerLeg;
    EXPECT_DOUBLE_EQ(c.q_des[j], 0.0);
    if (is_front_leg(leg)) {
      EXPECT_NEAR(c.q_des[j + 1], 0.9, 1e-12);
      EXPECT_NEAR(c.q_des[j + 2], -1.1, 1e-12);
      EXPECT_NEAR(c.qd_des[j + 1], 1.0, 1e-12);
      EXPECT_NEAR(c.tau_ff[j + 2], 3.0, 1e-12);
    } else {
      EXPECT_NEAR(c.q_des[j + 1], 0.8, 1e-12);
      EXPECT_NEAR(c.q_des[j + 2], -1.2, 1e-12);
      EXPECT_NEAR(c.qd_des[j + 2], 4.0, 1e-12);
      EXPECT_NEAR(c.tau_ff[j + 1], 4.0, 1e-12);
    }
  }
}

TEST(FlipPlayer, AfterThePlanTheLegsHoldItsLastPoseWithoutFeedForward) {
  const JointCommand c = flip_play_command(two_knots(), 0.5);
  EXPECT_DOUBLE_EQ(c.q_des[kJointsPerLeg * 3 + 2], -1.3);
  EXPECT_DOUBLE_EQ(c.qd_des[1], 0.0);
  EXPECT_DOUBLE_EQ(c.tau_ff[1], 0.0);
  EXPECT_GT(c.kp[1], 0.0);
}

}  // namespace
}  // namespace cerebellum
