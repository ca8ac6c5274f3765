// The small parts of the standing controllers, each against an independent computation: the leg
// change sequence, the pose ramp, reachability of a pose, the rest classification, the stance frame.
#include <gtest/gtest.h>

#include <cmath>

#include <Eigen/Geometry>

#include "control/pose_ramp.hpp"
#include "control/pose_reach.hpp"
#include "control/self_righting.hpp"
#include "control/stance_frame.hpp"
#include "control/support_sequence.hpp"
#include "core/leg_kinematics.hpp"
#include "core/robot_model.hpp"

namespace cerebellum {
namespace {

TEST(SupportSequence, ShiftsUnloadsAndLiftsInOrderThenPutsDownInReverse) {
  SupportSequence sequence({0.8, 0.3, 0.5});
  sequence.request(2);
  double t = 0.0;
  // mid shift: still fully loaded, not lifted
  for (; t < 0.4 - 1e-9; t += 0.002) sequence.advance(0.002);
  EXPECT_EQ(sequence.leg(), 2);
  EXPECT_NEAR(sequence.shift(), 0.5, 0.01);
  EXPECT_EQ(sequence.load(), 1.0);
  EXPECT_EQ(sequence.lift(), 0.0);
  EXPECT_FALSE(sequence.in_air());
  // mid unload
  for (; t < 0.95 - 1e-9; t += 0.002) sequence.advance(0.002);
  EXPECT_EQ(sequence.shift(), 1.0);
  EXPECT_NEAR(sequence.load(), 0.5, 0.01);
  // lifted after 1.6 s in all
  for (; t < 1.61; t += 0.002) sequence.advance(0.002);
  EXPECT_TRUE(sequence.settled());
  EXPECT_TRUE(sequence.in_air());
  EXPECT_EQ(sequence.lift(), 1.0);
  EXPECT_EQ(sequence.progress(), 1.0);
  // another leg: this one comes down first (phase runs back to 0), then the new one goes up
  sequence.request(1);
  sequence.advance(0.25);
  EXPECT_EQ(sequence.leg(), 2);
  EXPECT_NEAR(sequence.lift(), 0.5, 1e-9);
  sequence.advance(1.3);
  EXPECT_EQ(sequence.leg(), 2);
  EXPECT_GT(sequence.shift(), 0.0);
  // all four down: the new leg takes over
  sequence.advance(0.05);
  EXPECT_EQ(sequence.leg(), 1);
  EXPECT_EQ(sequence.shift(), 0.0);
  sequence.advance(2.0);
  EXPECT_TRUE(sequence.settled());
  EXPECT_EQ(sequence.leg(), 1);
  // all down
  sequence.request(SupportSequence::kNoLeg);
  sequence.advance(1.61);
  EXPECT_EQ(sequence.leg(), SupportSequence::kNoLeg);
  EXPECT_TRUE(sequence.settled());
}

TEST(PoseRamp, MovesSmoothlyWithTheRateItReports) {
  PoseRamp ramp;
  BodyPose from;
  from.position = {0.0, 0.0, 0.2};
  ramp.hold(from);
  BodyPose goal;
  goal.rpy = {0.2, -0.1, 0.3};
  goal.position = {0.02, 0.0, 0.25};
  ramp.move_to(goal, 1.0);
  BodyPose previous = ramp.value();
  for (int i = 0; i < 500; ++i) {
    ramp.advance(0.002);
    // the reported rate is the derivative of the value (central difference at the half step)
    const Eigen::Vector3d numeric = (ramp.value().rpy - previous.rpy) / 0.002;
    EXPECT_LT((numeric - ramp.rate().rpy).norm(), 0.01);
    previous = ramp.value();
  }
  EXPECT_NEAR(ramp.fraction(), 1.0, 1e-9);
  EXPECT_TRUE(ramp.value().rpy.isApprox(goal.rpy));
  EXPECT_TRUE(ramp.rate().rpy.isZero());
  // the same goal again does not restart the move
  ramp.move_to(goal, 1.0);
  EXPECT_TRUE(ramp.arrived());
  // speed limits: the larger of the angle and distance times
  EXPECT_NEAR(move_duration_s(from, goal, {0.5, 0.1, 0.3}), 1.5707963267948966 * 0.3 / 0.5, 1e-9);
}

TEST(PoseReach, CutsAPoseBackToTheLastOneTheLegsCanHold) {
  // footholds (stance frame: ground at z = 0) straight under the hips
  Footholds footholds{};
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
    footholds[leg] =
        hip_position(leg) + Eigen::Vector3d(0.0, leg_side_sign(leg) * robot::kAbadLength, robot::kFootRadius);
  }
  BodyPose level;
  level.position = {0.0, 0.0, 0.235};
  BodyPose tilted = level;
  tilted.rpy = {0.0, 0.8, 0.0};
  ASSERT_TRUE(feet_reachable(level, footholds, kAllLegs));
  ASSERT_FALSE(feet_reachable(tilted, footholds, kAllLegs));
  const double s = reachable_fraction(level, tilted, footholds, kAllLegs);
  EXPECT_GT(s, 0.1);
  EXPECT_LT(s, 0.9);
  // independent check: at s every foot is within its leg's reach and joint ranges, a little
  // further one of them is not
  EXPECT_TRUE(feet_reachable(blend(level, tilted, s), footholds, kAllLegs));
  EXPECT_FALSE(feet_reachable(blend(level, tilted, s + 0.01), footholds, kAllLegs));
  // the leg that runs out: its foot is almost a full leg length away at s + 0.01
  const BodyPose beyond = blend(level, tilted, s + 0.01);
  double longest = 0.0;
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
    const Eigen::Vector3d in_body = rotation_from_rpy(beyond.rpy).transpose() * (footholds[leg] - beyond.position);
    const Eigen::Vector3d from_hip = in_body - hip_position(leg);
    longest = std::max(longest, std::sqrt(from_hip.squaredNorm() - robot::kAbadLength * robot::kAbadLength));
  }
  EXPECT_GT(longest, 0.26);
}

TEST(BodyRest, ClassifiesFromTheDirectionOfGravity) {
  const auto rolled = [](double roll, double pitch = 0.0) {
    return Eigen::Quaterniond(Eigen::AngleAxisd(0.7, Eigen::Vector3d::UnitZ()) *
                              Eigen::AngleAxisd(pitch, Eigen::Vector3d::UnitY()) *
                              Eigen::AngleAxisd(roll, Eigen::Vector3d::UnitX()));
  };
  EXPECT_EQ(body_rest(rolled(0.0)), BodyRest::Upright);
  EXPECT_EQ(body_rest(rolled(0.9)), BodyRest::Upright);
  EXPECT_EQ(body_rest(rolled(0.0, 0.9)), BodyRest::Upright);
  // roll +90 deg: the right side (-y) faces down
  EXPECT_EQ(body_rest(rolled(1.57)), BodyRest::OnRightSide);
  EXPECT_EQ(body_rest(rolled(-1.57)), BodyRest::OnLeftSide);
  EXPECT_EQ(body_rest(rolled(3.14)), BodyRest::UpsideDown);
  EXPECT_EQ(body_rest(rolled(-2.5)), BodyRest::UpsideDown);
}

TEST(StanceFrame, RecoversTheBodyPoseFromFootholdsAndJointAngles) {
  // a robot standing level at 0.24 m with feet under the hips, yawed by 1 rad
  RobotState state;
  state.rpy = {0.0, 0.0, 1.0};
  state.orientation = Eigen::AngleAxisd(1.0, Eigen::Vector3d::UnitZ());
  state.contact = {1, 1, 1, 1};
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
    const Eigen::Vector3d foot =
        hip_position(leg) + Eigen::Vector3d(0.0, leg_side_sign(leg) * robot::kAbadLength, -(0.24 - robot::kFootRadius));
    const LegIkResult ik = inverse_kinematics_in_body(leg, foot);
    for (std::size_t k = 0; k < kJointsPerLeg; ++k) state.q[3 * leg + k] = ik.q[static_cast<Eigen::Index>(k)];
    state.foot_position_body[leg] = foot_position_in_body(leg, ik.q);
  }
  StanceFrame frame;
  frame.anchor(state);
  EXPECT_NEAR(frame.anchored_pose().position.z(), 0.24, 1e-9);
  EXPECT_NEAR(frame.anchored_pose().rpy.z(), 0.0, 1e-12);
  EXPECT_NEAR(frame.centroid(kAllLegs).head<2>().norm(), 0.0, 1e-12);
  // the body rolls by 0.1 rad about its origin with the feet fixed: the joints change accordingly
  const Eigen::Matrix3d roll = rotation_from_rpy(Eigen::Vector3d(0.1, 0.0, 0.0));
  const Eigen::Vector3d origin = frame.anchored_pose().position;
  state.rpy.x() = 0.1;
  state.orientation =
      Eigen::AngleAxisd(1.0, Eigen::Vector3d::UnitZ()) * Eigen::AngleAxisd(0.1, Eigen::Vector3d::UnitX());
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
    const LegIkResult ik = inverse_kinematics_in_body(leg, roll.transpose() * (frame.foothold(leg) - origin));
    for (std::size_t k = 0; k < kJointsPerLeg; ++k) state.q[3 * leg + k] = ik.q[static_cast<Eigen::Index>(k)];
    state.foot_position_body[leg] = foot_position_in_body(leg, ik.q);
  }
  Eigen::Vector3d position, velocity;
  ASSERT_TRUE(frame.estimate(state, kAllLegs, position, velocity));
  EXPECT_LT((position - origin).norm(), 1e-9);
  EXPECT_NEAR(frame.body_rpy(state).x(), 0.1, 1e-12);
  EXPECT_TRUE(velocity.isZero(1e-12));
}

}  // namespace
}  // namespace cerebellum
