// Swing trajectories and footholds against hand-computed values and finite differences.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "control/locomotion/foothold.hpp"
#include "control/locomotion/swing_trajectory.hpp"

namespace cerebellum {
namespace {

TEST(SwingTrajectory, StartsEndsAndPeaksWhereItShould) {
  const Eigen::Vector3d start(0.0, 0.1, 0.02), end(0.2, 0.12, 0.02);
  const SwingPoint a = swing_point(start, end, 0.06, 0.0, 0.2);
  const SwingPoint mid = swing_point(start, end, 0.06, 0.5, 0.2);
  const SwingPoint b = swing_point(start, end, 0.06, 1.0, 0.2);
  EXPECT_TRUE(a.position.isApprox(start));
  EXPECT_TRUE(b.position.isApprox(end));
  EXPECT_NEAR(mid.position.z(), 0.08, 1e-12);
  EXPECT_NEAR(mid.position.x(), 0.1, 1e-12);
  EXPECT_LT(a.velocity.norm(), 1e-12);  // lift-off and touchdown at rest
  EXPECT_LT(b.velocity.norm(), 1e-12);
  EXPECT_NEAR(mid.velocity.z(), 0.0, 1e-12);
}

TEST(SwingTrajectory, VelocityIsTheTimeDerivativeOfPosition) {
  const Eigen::Vector3d start(0.0, 0.1, 0.0), end(0.25, 0.05, 0.01);
  const double duration = 0.18, h = 1e-6;
  for (double s : {0.1, 0.3, 0.49, 0.51, 0.7, 0.9}) {
    const Eigen::Vector3d numeric = (swing_point(start, end, 0.05, s + h, duration).position -
                                     swing_point(start, end, 0.05, s - h, duration).position) /
                                    (2 * h * duration);
    EXPECT_LT((numeric - swing_point(start, end, 0.05, s, duration).velocity).norm(), 1e-5) << s;
  }
}

TEST(Foothold, RaibertTermsAddUp) {
  FootholdConfig config;
  const Eigen::Vector3d hip(1.0, 0.2, 0.0);
  // no yaw: 0.5 * 0.2 s * 0.5 m/s + 0.1 * (0.5 - 0.4) = 0.05 + 0.01
  Eigen::Vector3d p =
      raibert_foothold(hip, {0.5, 0.0, 0.0}, {0.4, 0.0, 0.0}, {0.4, 0.0, 0.0}, 0.0, 0.0, 0.2, 0.25, config);
  EXPECT_NEAR(p.x(), 1.06, 1e-12);
  EXPECT_NEAR(p.y(), 0.2, 1e-12);
  // turning left at 1 rad/s while moving forward at 0.5 m/s needs 0.5 m/s^2 towards +y: a
  // pendulum of height 0.25 m gets it from a foot 0.25 / 9.81 * 0.5 m outside the body, half
  // of which is the offset at touchdown
  p = raibert_foothold(hip, {0.5, 0.0, 0.0}, {0.5, 0.0, 0.0}, {0.5, 0.0, 0.0}, 1.0, 0.0, 0.2, 0.25, config);
  EXPECT_NEAR(p.y(), 0.2 - 0.5 * 0.25 / 9.81 * 0.5, 1e-12);
}

TEST(Foothold, OffsetIsClampedInTheHeadingFrame) {
  FootholdConfig config;
  // running as commanded at 3 m/s each way: 0.45 m asked, the leg's reach given
  Eigen::Vector3d p = raibert_foothold(Eigen::Vector3d::Zero(), {3.0, -3.0, 0}, {3.0, -3.0, 0}, {3.0, -3.0, 0}, 0.0,
                                       0.0, 0.3, 0.25, config);
  EXPECT_DOUBLE_EQ(p.x(), config.max_offset_forward_m);
  EXPECT_DOUBLE_EQ(p.y(), -config.max_offset_lateral_m);
  // heading +y: the body's forward axis is world +y, its left is world -x
  p = raibert_foothold(Eigen::Vector3d::Zero(), {3.0, 3.0, 0}, {3.0, 3.0, 0}, {3.0, 3.0, 0}, 0.0, M_PI / 2, 0.3, 0.25,
                       config);
  EXPECT_NEAR(p.y(), config.max_offset_forward_m, 1e-12);
  EXPECT_NEAR(p.x(), config.max_offset_lateral_m, 1e-12);
}

TEST(Foothold, APushIsCaughtWithTheLongestStep) {
  FootholdConfig config;
  // 1 m/s sideways against a command of rest: beyond the push threshold
  const Eigen::Vector3d p =
      raibert_foothold(Eigen::Vector3d::Zero(), {0.0, 1.0, 0}, {0, 0, 0}, {0, 0, 0}, 0.0, 0.0, 0.3, 0.25, config);
  EXPECT_NEAR(p.y(), std::min(0.5 * 0.3 * 1.0 + config.velocity_gain * 1.0, config.max_offset_push_m), 1e-12);
  EXPECT_GT(p.y(), config.max_offset_lateral_m);
}

TEST(Foothold, ACommandChangeIsNoPushTheFootReachesOnlyAsFarAsInWalking) {
  FootholdConfig config;
  // backing at 0.7 m/s, the command turned to 0.1 m/s forward: 0.8 m/s from the command, but
  // the command of a second before was -0.8, 0.1 m/s from the body
  const Eigen::Vector3d p = raibert_foothold(Eigen::Vector3d::Zero(), {-0.7, 0.0, 0}, {0.1, 0, 0}, {-0.8, 0, 0}, 0.0,
                                             0.0, 0.36, 0.25, config);
  // 0.5 * 0.36 * -0.7 + 0.1 * (-0.7 - 0.1) = -0.206: the walking clamp, not the push's
  EXPECT_DOUBLE_EQ(p.x(), -config.max_offset_forward_m);
  // the same body shoved while the command stood still at 0.1 for a second: a push
  const Eigen::Vector3d pushed =
      raibert_foothold(Eigen::Vector3d::Zero(), {-0.7, 0.0, 0}, {0.1, 0, 0}, {0.1, 0, 0}, 0.0, 0.0, 0.36, 0.25, config);
  EXPECT_NEAR(pushed.x(), 0.5 * 0.36 * -0.7 + config.velocity_gain * (-0.7 - 0.1), 1e-12);
}

TEST(Foothold, CatchingAPushOnTheSpotStepsSidewaysWithTheCatchGainAndForwardAsWalking) {
  FootholdConfig config;
  config.velocity_gain = 0.1;
  config.catch_lateral_velocity_gain = 0.07;
  // 1 m/s sideways against a command of rest, stance 0.12 s: 0.5 * 0.12 * 1 + 0.07 * 1 = 0.13 m
  // (walking's k: 0.16 m)
  const Eigen::Vector3d sideways = raibert_foothold(Eigen::Vector3d::Zero(), {0.0, 1.0, 0}, {0, 0, 0}, {0, 0, 0}, 0.0,
                                                    0.0, 0.12, 0.25, config, true);
  EXPECT_NEAR(sideways.y(), 0.13, 1e-12);
  EXPECT_NEAR(sideways.x(), 0.0, 1e-12);
  // facing +y (yaw 90 degrees), the body's left is world -x: the same sideways push, turned
  const Eigen::Vector3d turned = raibert_foothold(Eigen::Vector3d::Zero(), {-1.0, 0.0, 0}, {0, 0, 0}, {0, 0, 0}, 0.0,
                                                  M_PI / 2, 0.12, 0.25, config, true);
  EXPECT_NEAR(turned.x(), -0.13, 1e-12);
  EXPECT_NEAR(turned.y(), 0.0, 1e-12);
  // along the body the catch steps as walking does: 0.06 + 0.1 = 0.16 m
  const Eigen::Vector3d forward = raibert_foothold(Eigen::Vector3d::Zero(), {1.0, 0.0, 0}, {0, 0, 0}, {0, 0, 0}, 0.0,
                                                   0.0, 0.12, 0.25, config, true);
  EXPECT_NEAR(forward.x(), 0.16, 1e-12);
  // below the push threshold (0.4 m/s) the walking k holds: 0.024 + 0.04 = 0.064 m
  const Eigen::Vector3d slow = raibert_foothold(Eigen::Vector3d::Zero(), {0.0, 0.4, 0}, {0, 0, 0}, {0, 0, 0}, 0.0, 0.0,
                                                0.12, 0.25, config, true);
  EXPECT_NEAR(slow.y(), 0.064, 1e-12);
}

}  // namespace
}  // namespace cerebellum
