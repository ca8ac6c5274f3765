// The body state estimator on hand-built frames: contact trust ramps, the contact schedule,
// a robot standing still, and non-finite input.
#include "estimation/body_state_estimator.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

#include "core/leg_kinematics.hpp"
#include "core/robot_model.hpp"

namespace cerebellum {
namespace {

constexpr double kDt = 0.002;

// standing at rest in the stand pose, every foot pushing down with force_n
SensorFrame standing_frame(double time_s, double force_n) {
  SensorFrame frame;
  frame.time_s = time_s;
  frame.q = robot::whole_body_pose(robot::kStandPose);
  frame.imu_accel = {0.0, 0.0, 9.81};
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
    const Vec3 q(frame.q[3 * leg], frame.q[3 * leg + 1], frame.q[3 * leg + 2]);
    const Vec3 tau = -foot_jacobian(leg, q).transpose() * Vec3(0.0, 0.0, force_n);
    for (int j = 0; j < 3; ++j) frame.tau[3 * leg + j] = tau[j];
  }
  return frame;
}

double stand_height() {
  return robot::kThighLength * std::cos(robot::deg(45)) + robot::kShankLength * std::cos(robot::deg(25)) +
         robot::kFootRadius;
}

TEST(ContactTrust, ForceContactRampsInOverTheRampTime) {
  EXPECT_EQ(force_contact_trust(1.0, 0.0, 0.02), 0.0);
  EXPECT_NEAR(force_contact_trust(1.0, 0.005, 0.02), 0.25, 1e-12);
  EXPECT_EQ(force_contact_trust(1.0, 0.05, 0.02), 1.0);
  EXPECT_NEAR(force_contact_trust(0.6, 0.05, 0.02), 0.6, 1e-12);
  EXPECT_EQ(force_contact_trust(0.0, 0.05, 0.02), 0.0);
  EXPECT_EQ(force_contact_trust(1.0, 0.0, 0.0), 1.0);  // no ramp
}

TEST(ContactTrust, ScheduleRampsAtBothEndsOfTheStance) {
  EXPECT_EQ(scheduled_contact_trust({1.0, 0.0}, 0.1), 0.0);
  EXPECT_NEAR(scheduled_contact_trust({1.0, 0.05}, 0.1), 0.5, 1e-12);
  EXPECT_EQ(scheduled_contact_trust({1.0, 0.5}, 0.1), 1.0);
  EXPECT_NEAR(scheduled_contact_trust({1.0, 0.97}, 0.1), 0.3, 1e-12);
  EXPECT_EQ(scheduled_contact_trust({1.0, 1.0}, 0.1), 0.0);
  EXPECT_NEAR(scheduled_contact_trust({0.4, 0.5}, 0.1), 0.4, 1e-12);
  EXPECT_EQ(scheduled_contact_trust({0.0, 0.5}, 0.1), 0.0);
}

TEST(TrunkOriginAcceleration, RemovesWhatTheRotationAddsAtTheImuAgainstFiniteDifferences) {
  // the origin accelerates steadily while the trunk turns ever faster about a tilted axis; the
  // IMU's world acceleration comes from differencing its world position twice
  const Eigen::Vector3d origin_accel(0.7, -0.3, 0.2), origin_velocity(1.2, 0.4, 0.0);
  const Eigen::Vector3d axis = Eigen::Vector3d(0.3, 1.0, 0.2).normalized();
  const double rate = 3.0, rate_change = 80.0;  // rad/s, rad/s^2: a bound's pitching
  const Eigen::Vector3d imu(robot::kImuPositionBody[0], robot::kImuPositionBody[1], robot::kImuPositionBody[2]);
  const auto rotation = [&](double t) {
    return Eigen::AngleAxisd(0.2 + rate * t + 0.5 * rate_change * t * t, axis).toRotationMatrix();
  };
  const auto imu_world = [&](double t) {
    return Eigen::Vector3d(origin_velocity * t + 0.5 * origin_accel * t * t + rotation(t) * imu);
  };
  const double t = 0.05, h = 1e-4;
  const Eigen::Vector3d imu_accel = (imu_world(t + h) - 2.0 * imu_world(t) + imu_world(t - h)) / (h * h);
  // a rotation about a fixed axis: the body rates lie along it
  const Eigen::Vector3d omega = axis * (rate + rate_change * t), alpha = axis * rate_change;
  const Eigen::Vector3d result = trunk_origin_acceleration(imu_accel, rotation(t), omega, alpha, imu);
  EXPECT_LT((result - origin_accel).norm(), 1e-4);
  // the correction is not small: uncorrected, the IMU's acceleration is meters per second squared off
  EXPECT_GT((imu_accel - origin_accel).norm(), 3.0);
}

TEST(BodyStateEstimator, StandingStillStaysPutAtTheKinematicHeight) {
  BodyStateEstimator estimator;
  RobotState state;
  for (int k = 0; k <= 1000; ++k) {
    estimator.update(standing_frame(k * kDt, 20.0), std::nullopt, state);
    ASSERT_TRUE(state.valid);
  }
  EXPECT_NEAR(state.position_world.x(), 0.0, 1e-9);
  EXPECT_NEAR(state.position_world.y(), 0.0, 1e-9);
  EXPECT_NEAR(state.position_world.z(), stand_height(), 1e-9);
  EXPECT_LT(state.velocity_world.norm(), 1e-9);
  EXPECT_NEAR(state.height_m, stand_height(), 1e-9);
  for (double trust : estimator.contact_trust()) EXPECT_EQ(trust, 1.0);
}

TEST(BodyStateEstimator, TrustFollowsForceContactsUnlessAPlanIsGiven) {
  BodyStateEstimatorConfig config;
  config.force_contact_ramp_s = 0.01;
  BodyStateEstimator estimator(config);
  RobotState state;
  double t = 0.0;
  for (int k = 0; k < 3; ++k, t += kDt) estimator.update(standing_frame(t, 20.0), std::nullopt, state);
  // two updates after the first (which only starts the filter): 4 ms into a 10 ms ramp
  EXPECT_NEAR(estimator.contact_trust()[0], 0.4, 1e-9);
  for (int k = 0; k < 10; ++k, t += kDt) estimator.update(standing_frame(t, 20.0), std::nullopt, state);
  EXPECT_EQ(estimator.contact_trust()[0], 1.0);

  // the plan: FR in swing, FL late in its stance, the rear feet mid-stance
  const ContactPlan plan = ContactSchedule{{{0.0, 0.0}, {1.0, 0.95}, {1.0, 0.5}, {1.0, 0.5}}};
  estimator.update(standing_frame(t, 20.0), plan, state);
  t += kDt;
  EXPECT_EQ(estimator.contact_trust()[0], 0.0);
  EXPECT_NEAR(estimator.contact_trust()[1], 0.5, 1e-9);
  EXPECT_EQ(estimator.contact_trust()[2], 1.0);
  // a plan with a NaN is refused: the previous plan stays in use
  const ContactPlan broken = ContactSchedule{{{std::nan(""), 0.5}, {1.0, 0.5}, {1.0, 0.5}, {1.0, 0.5}}};
  estimator.update(standing_frame(t, 20.0), broken, state);
  t += kDt;
  EXPECT_EQ(estimator.contact_trust()[0], 0.0);
  EXPECT_NEAR(estimator.contact_trust()[1], 0.5, 1e-9);

  // back to forces: no foot pushes, no trust
  estimator.update(standing_frame(t, -20.0), std::nullopt, state);
  for (double trust : estimator.contact_trust()) EXPECT_EQ(trust, 0.0);
}

TEST(BodyStateEstimator, NonFiniteFrameIsInvalidAndLeavesTheEstimateFinite) {
  BodyStateEstimator estimator;
  RobotState state;
  double t = 0.0;
  for (int k = 0; k < 100; ++k, t += kDt) estimator.update(standing_frame(t, 20.0), std::nullopt, state);
  const Eigen::Vector3d position = state.position_world;
  SensorFrame bad = standing_frame(t, 20.0);
  bad.imu_accel[2] = std::nan("");
  estimator.update(bad, std::nullopt, state);
  EXPECT_FALSE(state.valid);
  EXPECT_TRUE(state.position_world.allFinite());
  EXPECT_TRUE(state.velocity_world.allFinite());
  EXPECT_EQ(state.position_world, position);
  estimator.update(standing_frame(t + kDt, 20.0), std::nullopt, state);
  EXPECT_TRUE(state.valid);
  EXPECT_TRUE(estimator.filter().state().allFinite());

  estimator.reset();
  EXPECT_FALSE(estimator.filter().initialized());
}

}  // namespace
}  // namespace cerebellum
