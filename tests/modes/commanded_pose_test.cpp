// The pose a client's commands ask for: absolute or incremental, held inside the ranges, and the
// seed's pitch sign.
#include "modes/commanded_pose.hpp"

#include <gtest/gtest.h>

#include "control/stance_frame.hpp"

namespace cerebellum {
namespace {

HighLevelCommand pose_command(float roll, float pitch, float yaw, float x = 0.0f, float y = 0.0f) {
  HighLevelCommand c;
  c.rpy_des = {roll, pitch, yaw};
  c.pos_des = {x, y, 0.0f};
  return c;
}

TEST(CommandedPose, APositivePitchRaisesTheHeadAsTheSeedSays) {
  // the body's x axis (the nose) after the commanded attitude, in the level frame: z up
  const Eigen::Vector3d nose =
      rotation_from_rpy(body_rpy_from_command(Eigen::Vector3d(0.0, 0.3, 0.0))) * Eigen::Vector3d::UnitX();
  EXPECT_NEAR(nose.z(), std::sin(0.3), 1e-12) << "head up";
  // roll: the left side (body +y) rises; yaw: the nose turns left (+y)
  const Eigen::Vector3d left =
      rotation_from_rpy(body_rpy_from_command(Eigen::Vector3d(0.2, 0.0, 0.0))) * Eigen::Vector3d::UnitY();
  EXPECT_GT(left.z(), 0.0);
  const Eigen::Vector3d turned =
      rotation_from_rpy(body_rpy_from_command(Eigen::Vector3d(0.0, 0.0, 0.2))) * Eigen::Vector3d::UnitX();
  EXPECT_GT(turned.y(), 0.0);
}

TEST(CommandedPose, HeadUpThenHeadDownEndsLevel) {
  CommandedPose pose;
  pose.reset(0.25);
  EXPECT_FALSE(pose.add(pose_command(0.0f, 0.3f, 0.0f), 0.0, PoseControlRanges{}));
  EXPECT_NEAR(pose.rpy_des().y(), 0.3, 1e-6);
  EXPECT_FALSE(pose.add(pose_command(0.0f, -0.3f, 0.0f), 0.0, PoseControlRanges{}));
  EXPECT_NEAR(pose.rpy_des().norm(), 0.0, 1e-6);
  EXPECT_DOUBLE_EQ(pose.height_m(), 0.25);
}

TEST(CommandedPose, IncrementsAddUpAndTheSumIsHeldAtTheRangesEdgeAndReported) {
  const PoseControlRanges ranges;
  CommandedPose pose;
  pose.reset(ranges.default_height_m);
  EXPECT_FALSE(pose.add(pose_command(0.0f, 0.0f, 0.3f, 0.05f), 0.0, ranges));
  EXPECT_TRUE(pose.add(pose_command(0.0f, 0.0f, 0.3f, 0.05f), 0.0, ranges)) << "yaw 0.6 and x 0.10 are outside";
  EXPECT_DOUBLE_EQ(pose.rpy_des().z(), ranges.yaw.upper);
  EXPECT_DOUBLE_EQ(pose.offset_m().x(), ranges.offset_x.upper);
  // back from the edge: the clamped sum is where the next increment starts
  EXPECT_FALSE(pose.add(pose_command(0.0f, 0.0f, -0.45f, -0.08f), 0.0, ranges));
  EXPECT_NEAR(pose.rpy_des().z(), 0.0, 1e-6);
  EXPECT_NEAR(pose.offset_m().x(), 0.0, 1e-6);
  EXPECT_TRUE(pose.add(pose_command(0.0f, 0.0f, 0.0f), 1.0, ranges)) << "a height far above the range";
  EXPECT_DOUBLE_EQ(pose.height_m(), ranges.height.upper);
}

TEST(CommandedPose, AnAbsoluteCommandReplacesWhatTheIncrementsBuilt) {
  const QpStandRanges ranges;
  CommandedPose pose;
  pose.reset(ranges.default_height_m);
  pose.add(pose_command(0.1f, 0.1f, 0.1f, 0.02f, 0.02f), 0.0, ranges);
  EXPECT_FALSE(pose.set(pose_command(0.0f, -0.2f, 0.0f), 0.2, ranges));
  EXPECT_NEAR(pose.rpy_des().x(), 0.0, 1e-9);
  EXPECT_NEAR(pose.rpy_des().y(), -0.2, 1e-6);
  EXPECT_NEAR(pose.body_rpy().y(), 0.2, 1e-6) << "head down 0.2 is a right-handed pitch of +0.2";
  EXPECT_NEAR(pose.offset_m().norm(), 0.0, 1e-9);
  EXPECT_DOUBLE_EQ(pose.height_m(), 0.2);
}

}  // namespace
}  // namespace cerebellum
