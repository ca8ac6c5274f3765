// Gait 1's push detector: the capture point against the linear inverted pendulum's own answer (a
// pendulum started at the capture point's offset with that velocity comes to rest over its foot),
// the distance to the feet's rectangle against hand-placed feet, and when steps begin and end.
#include "control/locomotion/push_recovery.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

#include "core/robot_model.hpp"

namespace cerebellum {
namespace {

// a level trunk at height_m, turned by yaw, its feet at the corners of a 0.38 x 0.2 m rectangle
RobotState standing_state(double yaw, double height_m = 0.235) {
  RobotState state;
  state.valid = true;
  state.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()));
  state.rpy = {0.0, 0.0, yaw};
  state.position_world = {1.0, -2.0, height_m};
  state.height_m = height_m;
  state.foot_position_body = {Eigen::Vector3d(0.19, -0.1, -height_m), Eigen::Vector3d(0.19, 0.1, -height_m),
                              Eigen::Vector3d(-0.19, -0.1, -height_m), Eigen::Vector3d(-0.19, 0.1, -height_m)};
  return state;
}

TEST(CapturePoint, IsWhereTheLinearInvertedPendulumComesToRestOverItsFoot) {
  RobotState state = standing_state(0.0, 0.25);
  state.velocity_world = {0.4, -0.7, 0.0};
  const Eigen::Vector2d capture = capture_point_world(state);
  // integrate x'' = g / h (x - foot) from the trunk with the foot at the capture point: the
  // pendulum neither falls back nor over, it creeps to rest above the foot
  const double omega2 = robot::kGravityMPerS2 / 0.25;
  Eigen::Vector2d x = state.position_world.head<2>();
  Eigen::Vector2d v = state.velocity_world.head<2>();
  const double dt = 1e-5;
  for (int i = 0; i < 100000; ++i) {  // 1 s: four time constants
    v += omega2 * (x - capture) * dt;
    x += v * dt;
  }
  EXPECT_LT(v.norm(), 0.02 * 0.8);
  EXPECT_LT((x - capture).norm(), 0.01);
}

TEST(DistanceOutsideFeet, IsNegativeInsideAndTheEuclideanGapOutsideInTheHeadingFrame) {
  const double yaw = 0.7;
  const RobotState state = standing_state(yaw);
  const Eigen::Rotation2Dd heading(yaw);
  const Eigen::Vector2d trunk = state.position_world.head<2>();
  // inside, 0.04 m from the nearest (lateral) edge
  EXPECT_NEAR(distance_outside_feet(state, trunk + heading * Eigen::Vector2d(0.05, 0.06)), -0.04, 1e-9);
  // beside the rectangle
  EXPECT_NEAR(distance_outside_feet(state, trunk + heading * Eigen::Vector2d(0.0, 0.25)), 0.15, 1e-9);
  // beyond a corner: the distance to the corner
  EXPECT_NEAR(distance_outside_feet(state, trunk + heading * Eigen::Vector2d(0.22, -0.14)), std::hypot(0.03, 0.04),
              1e-9);
}

TEST(PushRecovery, AStandingTrunkDoesNotStep) {
  PushRecovery recovery;
  RobotState state = standing_state(0.2);
  state.velocity_world = {0.05, -0.05, 0.0};
  state.omega_world = {0.2, -0.2, 0.0};
  for (int i = 0; i < 500; ++i) EXPECT_FALSE(recovery.update(state, 0.002));
  EXPECT_EQ(recovery.recoveries(), 0);
}

TEST(PushRecovery, StepsWhenTheCapturePointLeavesTheFeetOrTheTrunkTipsOrIsShovedAndStandsOnceAtRest) {
  const PushRecoveryConfig config;
  struct Case {
    Eigen::Vector3d velocity;
    double tip_rate_rad_s;
    Eigen::Vector3d accel;
    bool steps;
  };
  const Eigen::Vector3d still = Eigen::Vector3d::Zero();
  for (const Case& c : {
           // sideways at 0.2 m/s the capture point is 0.03 m out from the trunk: inside, 0.07 from the edge
           Case{{0.0, 0.2, 0.0}, 0.0, still, false},
           // at 0.6 m/s it is 0.093 m out: within the 0.06 m margin of the edge at 0.1
           Case{{0.0, 0.6, 0.0}, 0.0, still, true},
           Case{still, 1.5, still, true},
           // backward at 0.5 m/s the capture point is well inside (0.077 m behind, the feet at 0.19)
           // but the speed says a push
           Case{{-0.5, 0.0, 0.0}, 0.0, still, true},
           // at 0.35 m/s: a steady push (6 m/s^2) is held on planted feet, a blow (12 m/s^2) is not
           Case{{-0.35, 0.0, 0.0}, 0.0, {-6.0, 0.0, 0.0}, false},
           Case{{-0.35, 0.0, 0.0}, 0.0, {-12.0, 0.0, 0.0}, true},
       }) {
    PushRecovery recovery(config);
    RobotState state = standing_state(0.0);
    state.velocity_world = c.velocity;
    state.omega_world = {c.tip_rate_rad_s, 0.0, 0.0};
    state.accel_world = c.accel;
    EXPECT_EQ(recovery.update(state, 0.002), c.steps)
        << c.velocity.transpose() << " tip " << c.tip_rate_rad_s << " accel " << c.accel.transpose();
    if (!c.steps) continue;
    // at rest: it stands again after the hold, not before
    state.velocity_world.setZero();
    state.omega_world.setZero();
    state.accel_world.setZero();
    const int hold_ticks = static_cast<int>(std::ceil(config.settle_hold_s / 0.002));
    for (int i = 0; i < hold_ticks - 2; ++i) EXPECT_TRUE(recovery.update(state, 0.002));
    for (int i = 0; i < 3; ++i) recovery.update(state, 0.002);
    EXPECT_FALSE(recovery.stepping());
    EXPECT_EQ(recovery.recoveries(), 1);
  }
}

TEST(PushRecovery, AnInvalidStateChangesNothing) {
  PushRecovery recovery;
  RobotState state = standing_state(0.0);
  state.velocity_world = {0.0, 2.0, 0.0};
  state.valid = false;
  EXPECT_FALSE(recovery.update(state, 0.002));
}

}  // namespace
}  // namespace cerebellum
