// The passive trot's force estimate and admittance: the estimate is the trunk's m a minus the
// ground forces the stance legs' torques balance (checked with a Jacobian by finite differences of
// the forward kinematics), swing legs do not count, and a steady pull becomes a steady walking
// velocity that ends once the pull does.
#include "control/locomotion/passive_follow.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "core/leg_kinematics.hpp"

namespace cerebellum {
namespace {

// d foot / d q by central differences of the body-frame forward kinematics
Eigen::Matrix3d numeric_jacobian(std::size_t leg, const Eigen::Vector3d& q) {
  Eigen::Matrix3d j;
  const double h = 1e-6;
  for (int k = 0; k < 3; ++k) {
    Eigen::Vector3d plus = q, minus = q;
    plus[k] += h;
    minus[k] -= h;
    j.col(k) = (foot_position_in_body(leg, plus) - foot_position_in_body(leg, minus)) / (2 * h);
  }
  return j;
}

// a standing robot turned by `yaw`, accelerating at `accel_world`, each foot in `contact` pressed
// by the ground with `ground_world[leg]`
RobotState loaded_state(double yaw, const Eigen::Vector3d& accel_world,
                        const std::array<Eigen::Vector3d, 4>& ground_world, const std::array<double, 4>& contact) {
  RobotState state;
  state.valid = true;
  state.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()) *
                                         Eigen::AngleAxisd(0.05, Eigen::Vector3d::UnitY()));
  state.rpy = {0.0, 0.05, yaw};
  state.accel_world = accel_world;
  state.contact = contact;
  const Eigen::Matrix3d world_to_body = state.orientation.toRotationMatrix().transpose();
  for (std::size_t leg = 0; leg < 4; ++leg) {
    const Eigen::Vector3d q(0.05 * (leg % 2 ? 1 : -1), 0.8 + 0.05 * leg, -1.3 - 0.04 * leg);
    const Eigen::Vector3d tau = -numeric_jacobian(leg, q).transpose() * (world_to_body * ground_world[leg]);
    for (int j = 0; j < 3; ++j) {
      state.q[3 * leg + j] = q[j];
      state.tau[3 * leg + j] = tau[j];
    }
  }
  return state;
}

TEST(ExternalForce, IsMassTimesAccelerationMinusTheGroundForcesOnTheFeetInContact) {
  const std::array<Eigen::Vector3d, 4> ground{Eigen::Vector3d(-3.0, 1.0, 20.0), Eigen::Vector3d(-4.0, -2.0, 21.0),
                                              Eigen::Vector3d(-2.5, 0.5, 22.0), Eigen::Vector3d(-5.0, 0.0, 19.0)};
  const Eigen::Vector3d accel(0.4, -0.2, 0.0);
  const RobotState state = loaded_state(0.7, accel, ground, {1.0, 1.0, 1.0, 1.0});
  const double mass = 8.5;
  const Eigen::Vector3d expected = mass * accel - (ground[0] + ground[1] + ground[2] + ground[3]);
  const Eigen::Vector2d estimate = external_force_world(state, mass);
  EXPECT_NEAR(estimate.x(), expected.x(), 1e-4);
  EXPECT_NEAR(estimate.y(), expected.y(), 1e-4);
}

TEST(ExternalForce, IgnoresTheTorquesOfLegsInTheAir) {
  const std::array<Eigen::Vector3d, 4> ground{Eigen::Vector3d(-6.0, 0.0, 40.0), Eigen::Vector3d(9.0, 9.0, 9.0),
                                              Eigen::Vector3d(9.0, 9.0, 9.0), Eigen::Vector3d(-6.0, 0.0, 40.0)};
  const RobotState state = loaded_state(-0.3, Eigen::Vector3d::Zero(), ground, {1.0, 0.0, 0.0, 1.0});
  const Eigen::Vector2d estimate = external_force_world(state, 8.5);
  EXPECT_NEAR(estimate.x(), 12.0, 1e-4);
  EXPECT_NEAR(estimate.y(), 0.0, 1e-4);
}

// no foot down: the estimate is m a, so a state with a = F / m stands for a pull F
RobotState pulled_by(const Eigen::Vector2d& force_n, double mass_kg) {
  RobotState state;
  state.valid = true;
  state.accel_world = Eigen::Vector3d(force_n.x(), force_n.y(), 0.0) / mass_kg;
  return state;
}

TEST(PassiveFollow, ASteadyPullStartsFollowingAtForceBeyondTheDeadbandOverDamping) {
  PassiveFollowConfig config;
  config.bias_time_constant_s = 1e9;  // nothing learnt as bias: the admittance alone
  PassiveFollow follow(config);
  const Eigen::Vector2d pull(9.0, -12.0);  // 15 N
  // shorter than the hold: still standing
  for (int i = 0; i < 50; ++i) follow.update(pulled_by(pull, config.mass_kg), 0.002);
  EXPECT_FALSE(follow.following());
  for (int i = 0; i < 5000; ++i) follow.update(pulled_by(pull, config.mass_kg), 0.002);
  ASSERT_TRUE(follow.following());
  const Eigen::Vector2d expected = pull.normalized() * (pull.norm() - config.deadband_n) / config.damping_n_s_per_m;
  EXPECT_NEAR(follow.velocity_world().x(), expected.x(), 1e-3);
  EXPECT_NEAR(follow.velocity_world().y(), expected.y(), 1e-3);
}

TEST(PassiveFollow, ASuddenPullStartsFollowingWithinHalfASecond) {
  PassiveFollowConfig config;
  PassiveFollow follow(config);
  for (int i = 0; i < 1000; ++i) follow.update(pulled_by({0.0, 0.0}, config.mass_kg), 0.002);
  int ticks = 0;
  while (!follow.following() && ticks < 1000) {
    follow.update(pulled_by({0.0, -15.0}, config.mass_kg), 0.002);
    ++ticks;
  }
  EXPECT_LT(ticks * 0.002, 0.5);
}

TEST(PassiveFollow, AnErrorThatCreepsUpWhileStandingIsLearntAndNeverStartsTheTrot) {
  PassiveFollowConfig config;
  PassiveFollow follow(config);
  // 0 -> 12 N over 12 s, far beyond the start threshold in the end
  for (int i = 0; i <= 6000; ++i) {
    follow.update(pulled_by({i * 0.002, 0.0}, config.mass_kg), 0.002);
    ASSERT_FALSE(follow.following()) << "at " << i * 0.002 << " s";
  }
}

TEST(PassiveFollow, AForceInsideTheDeadbandNeverMovesIt) {
  PassiveFollowConfig config;
  PassiveFollow follow(config);
  for (int i = 0; i < 5000; ++i) follow.update(pulled_by({config.deadband_n * 0.9, 0.0}, config.mass_kg), 0.002);
  EXPECT_FALSE(follow.following());
  EXPECT_EQ(follow.velocity_world().norm(), 0.0);
}

TEST(PassiveFollow, StopsFollowingSoonAfterThePullEnds) {
  PassiveFollowConfig config;
  PassiveFollow follow(config);
  for (int i = 0; i < 2000; ++i) follow.update(pulled_by({15.0, 0.0}, config.mass_kg), 0.002);
  ASSERT_TRUE(follow.following());
  int ticks = 0;
  while (follow.following() && ticks < 5000) {
    follow.update(pulled_by({0.0, 0.0}, config.mass_kg), 0.002);
    ++ticks;
  }
  EXPECT_FALSE(follow.following());
  // filter, velocity decay and the quiet hold: well under a second
  EXPECT_LT(ticks * 0.002, 1.0);
  EXPECT_EQ(follow.velocity_world().norm(), 0.0);
}

TEST(PassiveFollow, NonFiniteStateLeavesItUnchanged) {
  PassiveFollow follow;
  RobotState state = pulled_by({15.0, 0.0}, robot::kTotalMassKg);
  state.accel_world.x() = std::numeric_limits<double>::quiet_NaN();
  for (int i = 0; i < 1000; ++i) follow.update(state, 0.002);
  EXPECT_FALSE(follow.following());
  EXPECT_TRUE(follow.force_world().allFinite());
}

}  // namespace
}  // namespace cerebellum
