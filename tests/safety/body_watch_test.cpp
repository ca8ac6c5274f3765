// The body checks on synthetic states: orientation limit, the interface's foot workspace (its
// formulas with the numbers of the reference), and the report that combines them.
#include "safety/body_watch.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "core/leg_kinematics.hpp"

namespace cerebellum {
namespace {

TEST(OrientationError, IsAtOrBeyondTheLimitInRollOrPitch) {
  RobotState s;
  s.rpy = {1.29, 0.0, 3.0};
  EXPECT_FALSE(orientation_error(s));
  s.rpy = {-1.3, 0.0, 0.0};
  EXPECT_TRUE(orientation_error(s));
  s.rpy = {0.0, 1.31, 0.0};
  EXPECT_TRUE(orientation_error(s));
}

RobotState standing_feet() {
  RobotState state;
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
    state.foot_position_body[leg] = foot_position_in_body(leg, Vec3(0.0, 0.785, -1.22));
  }
  return state;
}

TEST(FootWorkspace, BoundsAreTheInterfaceFormulas) {
  const FootWorkspace w;
  EXPECT_NEAR(w.forward_m, 0.2546, 1e-4);
  EXPECT_NEAR(w.lateral_m, 0.294 * 0.62879 + 0.094 * 0.77757, 1e-4);
  EXPECT_NEAR(w.lowest_m, -0.3087, 1e-4);
  EXPECT_NEAR(w.highest_m, -0.049, 1e-6);
}

TEST(FootWorkspace, StandingFeetAreInsideAndEachAxisHasItsBit) {
  EXPECT_EQ(foot_position_error_bits(standing_feet()), 0);
  RobotState state = standing_feet();
  state.foot_position_body[0].x() += 0.3;   // FR forward
  state.foot_position_body[1].y() += 0.3;   // FL lateral
  state.foot_position_body[3].z() = -0.02;  // RL too high
  EXPECT_EQ(foot_position_error_bits(state), (1 << 0) | (1 << 4) | (1 << 11));
}

TEST(FootWorkspace, DefaultsAreTheReferenceFormulasWithItsLiterals) {
  // cyberdog2-highlevel.md: L = 0.294 m, abad = 0.094 m, sin 60 deg, 0.68 rad
  const FootWorkspace w;
  EXPECT_DOUBLE_EQ(w.forward_m, 0.294 * std::sqrt(3.0) / 2.0);
  EXPECT_DOUBLE_EQ(w.lateral_m, 0.294 * std::sin(0.68) + 0.094 * std::cos(0.68));
  EXPECT_DOUBLE_EQ(w.lowest_m, -std::hypot(0.294, 0.094));
  EXPECT_DOUBLE_EQ(w.highest_m, -0.294 / 6.0);
}

TEST(FootWorkspace, AClampedFootTargetPassesTheWatchWithItsMarginAndOneInsideIsLeftAlone) {
  const FootWorkspace w;
  const double margin_m = 0.02;
  const RobotState inside = standing_feet();
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
    const Vec3 foot = inside.foot_position_body[leg];
    EXPECT_TRUE(clamp_into_foot_workspace(leg, foot, w, margin_m).isApprox(foot, 1e-12)) << leg;
  }
  // far out on every axis, both ways: the clamped target is inside the workspace shrunk by the margin
  FootWorkspace shrunk = w;
  shrunk.forward_m -= margin_m;
  shrunk.lateral_m -= margin_m;
  shrunk.lowest_m += margin_m;
  shrunk.highest_m -= margin_m;
  for (const Vec3& offset : {Vec3(0.5, 0.4, 0.3), Vec3(-0.5, -0.4, -0.6), Vec3(0.3, 0.0, 0.1), Vec3(0.0, -0.5, 0.0)}) {
    RobotState state = standing_feet();
    for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
      state.foot_position_body[leg] =
          clamp_into_foot_workspace(leg, state.foot_position_body[leg] + offset, w, margin_m);
    }
    EXPECT_EQ(foot_position_error_bits(state, shrunk), 0) << offset.transpose();
    // and it lies on the shrunk workspace's edge, not deeper inside
    EXPECT_NE(foot_position_error_bits(state, FootWorkspace{w.forward_m - 0.021, w.lateral_m - 0.021,
                                                            w.lowest_m + 0.021, w.highest_m - 0.021}),
              0)
        << offset.transpose();
  }
}

TEST(BodyCheck, ReportsTheOrientationAlwaysAndTheFeetOnlyWhenAsked) {
  RobotState state = standing_feet();
  state.rpy = {0.0, -1.4, 0.0};
  state.foot_position_body[2].z() = -0.5;  // RR too low
  const SafetyReport feet = check_body(state, true);
  EXPECT_TRUE(feet.orientation_error);
  EXPECT_EQ(feet.footpos_error, foot_position_error_bits(state));
  EXPECT_EQ(feet.footpos_error, 1 << 8);
  EXPECT_TRUE(feet.body_fault());
  const SafetyReport no_feet = check_body(state, false);
  EXPECT_TRUE(no_feet.orientation_error);
  EXPECT_EQ(no_feet.footpos_error, 0);
  EXPECT_EQ(no_feet.flags, kGuardOk);
  EXPECT_FALSE(check_body(standing_feet(), true).body_fault());
}

}  // namespace
}  // namespace cerebellum
