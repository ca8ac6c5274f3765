// The kinematic estimator against hand-built frames: orientation, acceleration, contacts, height.
#include "estimation/kinematic_estimator.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

#include "core/leg_kinematics.hpp"
#include "core/robot_model.hpp"

namespace cerebellum {
namespace {

SensorFrame standing_frame() {
  SensorFrame frame;
  frame.q = robot::whole_body_pose(robot::kStandPose);
  frame.imu_accel = {0.0, 0.0, robot::kGravityMPerS2};
  return frame;
}

// joint torques that make each foot push down with force_n (statics: tau = -J^T f_ground)
void push_down(SensorFrame& frame, double force_n) {
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
    const Vec3 q(frame.q[3 * leg], frame.q[3 * leg + 1], frame.q[3 * leg + 2]);
    const Vec3 tau = -foot_jacobian(leg, q).transpose() * Vec3(0.0, 0.0, force_n);
    for (int j = 0; j < 3; ++j) frame.tau[3 * leg + j] = tau[j];
  }
}

TEST(KinematicEstimator, RollPitchYawFromTheImuQuaternion) {
  SensorFrame frame = standing_frame();
  const Eigen::Quaterniond q = Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitZ()) *
                               Eigen::AngleAxisd(-0.2, Eigen::Vector3d::UnitY()) *
                               Eigen::AngleAxisd(0.1, Eigen::Vector3d::UnitX());
  frame.imu_quat = {q.w(), q.x(), q.y(), q.z()};
  KinematicEstimator estimator;
  RobotState state;
  estimator.update(frame, std::nullopt, state);
  ASSERT_TRUE(state.valid);
  EXPECT_NEAR(state.rpy.x(), 0.1, 1e-12);
  EXPECT_NEAR(state.rpy.y(), -0.2, 1e-12);
  EXPECT_NEAR(state.rpy.z(), 0.3, 1e-12);
}

TEST(KinematicEstimator, GravityIsRemovedFromTheAccelerometerForTheAccelerationAndKeptInTheSpecificForce) {
  SensorFrame frame = standing_frame();
  frame.imu_accel = {1.0, 0.0, robot::kGravityMPerS2};
  KinematicEstimator estimator;
  RobotState state;
  estimator.update(frame, std::nullopt, state);
  EXPECT_NEAR(state.accel_world.x(), 1.0, 1e-12);
  EXPECT_NEAR(state.accel_world.z(), 0.0, 1e-12);
  // what the interfaces publish: the accelerometer as it reads
  EXPECT_EQ(state.specific_force_body, Eigen::Vector3d(1.0, 0.0, robot::kGravityMPerS2));
}

TEST(KinematicEstimator, OnATiltTheAccelerationTurnsTheSpecificForceIntoTheWorldBeforeGravityIsRemoved) {
  // at rest rolled 0.4 rad: the accelerometer reads gravity's reaction in the tilted body frame
  SensorFrame frame = standing_frame();
  const Eigen::Quaterniond roll(Eigen::AngleAxisd(0.4, Eigen::Vector3d::UnitX()));
  frame.imu_quat = {roll.w(), roll.x(), roll.y(), roll.z()};
  const Eigen::Vector3d reading = roll.conjugate() * Eigen::Vector3d(0.0, 0.0, robot::kGravityMPerS2);
  frame.imu_accel = {reading.x(), reading.y(), reading.z()};
  KinematicEstimator estimator;
  RobotState state;
  estimator.update(frame, std::nullopt, state);
  EXPECT_LT(state.accel_world.norm(), 1e-12);
  EXPECT_LT((state.specific_force_body - reading).norm(), 1e-12);
}

TEST(KinematicEstimator, ContactsFromFootForceAndHeightFromStanceFeet) {
  SensorFrame frame = standing_frame();
  push_down(frame, 20.0);
  frame.tau[3] = frame.tau[4] = frame.tau[5] = 0.0;  // FL carries nothing
  KinematicEstimator estimator;
  RobotState state;
  estimator.update(frame, std::nullopt, state);
  EXPECT_EQ(state.contact[0], 1.0);
  EXPECT_EQ(state.contact[1], 0.0);
  EXPECT_EQ(state.contact[2], 1.0);
  EXPECT_EQ(state.contact[3], 1.0);
  const double expected = 0.12 * std::cos(robot::deg(45)) + 0.17391 * std::cos(robot::deg(25)) + 0.019;
  EXPECT_NEAR(state.height_m, expected, 1e-9);
}

TEST(KinematicEstimator, PullingUpIsNotContact) {
  SensorFrame frame = standing_frame();
  push_down(frame, -20.0);
  KinematicEstimator estimator;
  RobotState state;
  estimator.update(frame, std::nullopt, state);
  for (double c : state.contact) EXPECT_EQ(c, 0.0);
}

TEST(KinematicEstimator, NonFiniteFrameIsInvalid) {
  SensorFrame frame = standing_frame();
  frame.q[7] = std::nan("");
  KinematicEstimator estimator;
  RobotState state;
  estimator.update(frame, std::nullopt, state);
  EXPECT_FALSE(state.valid);
  frame = standing_frame();
  frame.imu_quat = {0.0, 0.0, 0.0, 0.0};
  estimator.update(frame, std::nullopt, state);
  EXPECT_FALSE(state.valid);
}

}  // namespace
}  // namespace cerebellum
