// Clamping and decoding of the command fields the standing modes use.
#include "modes/command_ranges.hpp"
#include "modes/commanded_pose.hpp"

#include <gtest/gtest.h>

#include "modes/locomotion_gait.hpp"
#include "modes/locomotion_mode.hpp"
#include "modes/qp_stand_mode.hpp"
#include "modes/walking_gaits.hpp"

namespace cerebellum {
namespace {

TEST(CommandRanges, ContactBitsNameTheSingleLiftedLeg) {
  EXPECT_EQ(lifted_leg_from_contact(0x0F), kNoLiftedLeg);
  EXPECT_EQ(lifted_leg_from_contact(0x00), kNoLiftedLeg);  // field left unset by the client
  EXPECT_EQ(lifted_leg_from_contact(0b1110), 0);           // FR
  EXPECT_EQ(lifted_leg_from_contact(0b1101), 1);           // FL
  EXPECT_EQ(lifted_leg_from_contact(0b1011), 2);           // RR
  EXPECT_EQ(lifted_leg_from_contact(0b0111), 3);           // RL
  EXPECT_EQ(lifted_leg_from_contact(0x1E), 0);             // high bits ignored
  EXPECT_EQ(lifted_leg_from_contact(0b1100), kInvalidContact);
  EXPECT_EQ(lifted_leg_from_contact(0b1000), kInvalidContact);
}

TEST(CommandRanges, FootOffsetComesFromTheFrontOrRearTripleAndIsClamped) {
  HighLevelCommand c;
  // nothing given: straight up by the default lift
  EXPECT_TRUE(lifted_foot_offset(c, 0).isApprox(Eigen::Vector3d(0.0, 0.0, 0.08)));
  c.foot_pose = {0.05f, -0.02f, 0.1f, 0.5f, 0.5f, -0.3f};
  EXPECT_TRUE(lifted_foot_offset(c, 1).isApprox(Eigen::Vector3d(0.05, -0.02, 0.1), 1e-6));
  // rear legs use foot_pose[3..5], clamped to x 0.15, y 0.10, z >= 0
  EXPECT_TRUE(lifted_foot_offset(c, 3).isApprox(Eigen::Vector3d(0.15, 0.10, 0.0), 1e-6));
}

TEST(CommandRanges, QpStandGoalIsTheCommandedPoseWithTheCommandsLiftedLeg) {
  HighLevelCommand c;
  c.mode = 3;
  c.rpy_des = {-1.0f, 1.0f, 2.0f};
  c.pos_des = {0.3f, -0.3f, 0.5f};
  c.contact = 0b0111;
  CommandedPose pose;
  EXPECT_TRUE(pose.set(c, c.pos_des[2], QpStandRanges{}));
  const QpStandGoal goal = qp_stand_goal(pose, c, FootOffsetRanges{});
  EXPECT_DOUBLE_EQ(goal.pose.rpy.x(), -0.52);
  EXPECT_DOUBLE_EQ(goal.pose.rpy.y(), -0.3) << "0.3 head up is a right-handed pitch of -0.3";
  EXPECT_DOUBLE_EQ(goal.pose.rpy.z(), 0.65);
  EXPECT_DOUBLE_EQ(goal.pose.position.x(), 0.05);
  EXPECT_DOUBLE_EQ(goal.pose.position.y(), -0.05);
  EXPECT_DOUBLE_EQ(goal.pose.position.z(), 0.32);
  EXPECT_EQ(goal.lifted_leg, 3);
}

TEST(CommandRanges, LocomotionClampsVelocityPerGaitAndStandFields) {
  GaitRegistry gaits;
  LocomotionMode mode(gaits);
  HighLevelCommand c;
  c.mode = 11;
  c.gait_id = 10;  // flying trot: vx -1.2..1.6, vy +-0.55, yaw +-2.5
  c.vel_des = {3.0f, -1.0f, 0.5f};
  c.rpy_des = {0.0f, -0.9f, 0.0f};
  c.pos_des = {0.0f, 0.0f, 0.1f};
  c.step_height = {0.1f, -0.1f};
  const LocomotionCommand l = mode.clamped(c);
  EXPECT_TRUE(l.velocity.isApprox(Eigen::Vector3d(1.6, -0.55, 0.5), 1e-6));
  EXPECT_DOUBLE_EQ(l.pitch_rad, 0.25) << "0.9 head down held at 0.25: a right-handed pitch of +0.25";
  EXPECT_DOUBLE_EQ(l.height_m, 0.2);
  EXPECT_DOUBLE_EQ(l.step_height_m[0], 0.06);
  EXPECT_DOUBLE_EQ(l.step_height_m[1], 0.005);  // the MC's floor, not the gait's default
  c.gait_id = 2;                                // pronk: vx -0.1..0.2
  EXPECT_DOUBLE_EQ(mode.clamped(c).velocity.x(), 0.2);
  // a stand has no velocity
  c.gait_id = 1;
  EXPECT_TRUE(mode.clamped(c).velocity.isZero());
}

TEST(CommandRanges, ConfiguredLimitsWidenTheClampAndTravelWithTheCommandToTheController) {
  LocomotionLimits limits;
  EXPECT_FALSE(limits.set_velocity(1, {Eigen::Vector3d::Constant(-1), Eigen::Vector3d::Constant(1)}))
      << "a stand has no velocity to widen";
  EXPECT_FALSE(limits.set_velocity(55, {Eigen::Vector3d::Constant(-1), Eigen::Vector3d::Constant(1)}));
  ASSERT_TRUE(limits.set_velocity(10, {Eigen::Vector3d(-1.2, -0.55, -2.5), Eigen::Vector3d(2.5, 0.55, 2.5)}));
  limits.set_step_height({kStepHeightRange.lower, 0.1});
  GaitRegistry gaits;
  LocomotionMode mode(gaits, limits);
  HighLevelCommand c;
  c.mode = 11;
  c.gait_id = 10;
  c.vel_des = {3.0f, 0.0f, 0.0f};
  c.step_height = {0.12f, 0.08f};
  const LocomotionCommand l = mode.clamped(c);
  EXPECT_DOUBLE_EQ(l.velocity.x(), 2.5);
  ASSERT_TRUE(l.velocity_limits.has_value());
  EXPECT_DOUBLE_EQ(l.velocity_limits->max.x(), 2.5);
  EXPECT_DOUBLE_EQ(l.step_height_m[0], 0.1);
  EXPECT_NEAR(l.step_height_m[1], 0.08, 1e-6);
  // the controller's own clamp and gait changes read the limits the mode clamped to
  const LocomotionTarget target = locomotion_target_from(l);
  EXPECT_DOUBLE_EQ(target.gait.velocity_max[0], 2.5);
  c.gait_id = 3;  // not widened: the product's
  EXPECT_DOUBLE_EQ(mode.clamped(c).velocity.x(), find_gait(3)->velocity_max[0]);
  c.gait_id = 1;
  EXPECT_FALSE(mode.clamped(c).velocity_limits.has_value());
}

TEST(CommandRanges, UnregisteredGaitsAreRefusedWithTheirName) {
  GaitRegistry gaits;
  LocomotionMode mode(gaits);
  HighLevelCommand c;
  c.mode = 11;
  c.gait_id = 3;
  EXPECT_STREQ(mode.check(c), "gait 3 (medium trot) not available yet");
  c.gait_id = 85;
  EXPECT_STREQ(mode.check(c), "user gait slots 80..100 not available yet");
  c.gait_id = 55;
  EXPECT_STREQ(mode.check(c), "mode 11 has no such gait");
}

}  // namespace
}  // namespace cerebellum
