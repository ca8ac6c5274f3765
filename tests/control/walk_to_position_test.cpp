// Walking to a target: the command points at the target in the body frame whatever the heading,
// respects the speed limits, turns toward the target heading, stops within the arrival band and
// walks again only once clearly away; and a simulated point robot following it arrives without
// orbiting.
#include "control/walk_to_position.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace cerebellum {
namespace {

TEST(WalkToPosition, PointsAtTheTargetInTheBodyFrameWhateverTheHeading) {
  WalkToPosition walk;
  Pose2d trunk;
  trunk.yaw_rad = 1.5707963267948966;  // facing +y
  Pose2d target;
  target.position = {1.0, 0.0};  // to the trunk's right
  target.yaw_rad = trunk.yaw_rad;
  const WalkToPositionOutput out = walk.update(trunk, target, 0.6);
  EXPECT_NEAR(out.velocity.x(), 0.0, 1e-9);
  EXPECT_LT(out.velocity.y(), 0.0);
  EXPECT_NEAR(out.velocity.y(), -0.3, 1e-9) << "lateral share of the speed limit";
  EXPECT_NEAR(out.velocity.z(), 0.0, 1e-9);
}

TEST(WalkToPosition, KeepsWithinTheSpeedLimitAndTurnsTowardTheTargetHeading) {
  WalkToPosition walk;
  Pose2d trunk;
  Pose2d target;
  target.position = {5.0, 1.0};
  target.yaw_rad = -3.0;
  const WalkToPositionOutput out = walk.update(trunk, target, 0.5);
  EXPECT_LE(out.velocity.head<2>().norm(), 0.5 + 1e-12);
  EXPECT_GT(out.velocity.x(), 0.0);
  EXPECT_LT(out.velocity.z(), 0.0);
  EXPECT_GE(out.velocity.z(), -WalkToPositionConfig{}.max_yaw_rate_rad_s);
}

TEST(WalkToPosition, StopsWithinTheArrivalBandAndWalksAgainOnlyWhenClearlyAway) {
  WalkToPosition walk;
  Pose2d target;
  Pose2d trunk;
  trunk.position = {0.02, 0.0};
  EXPECT_TRUE(walk.update(trunk, target, 0.6).arrived);
  trunk.position = {0.06, 0.0};  // beyond arrival, within leaving
  EXPECT_TRUE(walk.update(trunk, target, 0.6).arrived);
  trunk.position = {0.1, 0.0};
  const WalkToPositionOutput out = walk.update(trunk, target, 0.6);
  EXPECT_FALSE(out.arrived);
  EXPECT_LT(out.velocity.x(), 0.0);
}

TEST(WalkToPosition, APointRobotFollowingItArrivesFromEveryDirectionWithoutOrbiting) {
  for (int k = 0; k < 8; ++k) {
    WalkToPosition walk;
    Pose2d trunk;
    trunk.position = {2.0 * std::cos(k * 0.785), 2.0 * std::sin(k * 0.785)};
    trunk.yaw_rad = 0.3 * k;
    Pose2d target;
    target.yaw_rad = 0.5;
    double path_m = 0.0;
    bool arrived = false;
    for (int i = 0; i < 5000 && !arrived; ++i) {  // 10 s at 500 Hz
      const WalkToPositionOutput out = walk.update(trunk, target, 0.6);
      arrived = out.arrived;
      const double c = std::cos(trunk.yaw_rad), s = std::sin(trunk.yaw_rad);
      const Eigen::Vector2d step(c * out.velocity.x() - s * out.velocity.y(),
                                 s * out.velocity.x() + c * out.velocity.y());
      trunk.position += step * 0.002;
      trunk.yaw_rad += out.velocity.z() * 0.002;
      path_m += step.norm() * 0.002;
    }
    EXPECT_TRUE(arrived) << k;
    EXPECT_LT(trunk.position.norm(), WalkToPositionConfig{}.arrive_position_m + 1e-9) << k;
    // no orbit: the path is barely longer than the straight line
    EXPECT_LT(path_m, 2.0 * 1.1) << k;
  }
}

}  // namespace
}  // namespace cerebellum
