// The jump plan's maths against independent checks: the flight integrated step by step, the
// push's kinematics, its limits, and the standing legs' momentum against MuJoCo's own figures
// for the same model.
#include "control/jump/jump_plan.hpp"

#include <gtest/gtest.h>
#include <mujoco/mujoco.h>

#include <cmath>
#include <random>

#include "backend/sim_fixture.hpp"
#include "core/leg_kinematics.hpp"
#include "core/robot_model.hpp"

namespace cerebellum {
namespace {

using robot::kGravityMPerS2;

// the centre of mass's flight, integrated in small steps until it comes down to the touchdown
// height: its duration and horizontal travel
struct Flight {
  double duration_s = 0.0;
  Eigen::Vector2d travel_m = Eigen::Vector2d::Zero();
};
Flight integrate_flight(const Eigen::Vector3d& v0, double start_z, double end_z) {
  constexpr double kDt = 1e-6;
  Flight flight;
  Eigen::Vector3d v = v0;
  double z = start_z;
  while (v.z() > 0.0 || z > end_z) {
    z += v.z() * kDt;
    flight.travel_m += v.head<2>() * kDt;
    v.z() -= kGravityMPerS2 * kDt;
    flight.duration_s += kDt;
  }
  return flight;
}

TEST(JumpPlan, TheFlightLastsAsLongAsTheIntegratedBallisticPathAndTheDisplacementsAddUpToTheTarget) {
  const JumpLimits limits;
  for (const JumpTarget& target : {JumpTarget{{0.3, 0.0}, 0.0, 0.0, 0.0}, JumpTarget{{0.0, -0.2}, 0.0, 0.0, 0.0},
                                   JumpTarget{{0.2, 0.1}, 0.0, 0.0, -0.1}, JumpTarget{{0.0, 0.0}, 1.0, 0.1, 0.0}}) {
    const JumpPlan plan = plan_jump(target, limits);
    ASSERT_EQ(plan.shortfall, kJumpReachable);
    const Flight flight = integrate_flight(plan.com_takeoff_velocity_m_s, plan.takeoff_height_m,
                                           target.landing_ground_m + limits.touchdown_height_m);
    EXPECT_NEAR(plan.flight_duration_s, flight.duration_s, 1e-4);
    EXPECT_NEAR(plan.flight_travel_m.x(), flight.travel_m.x(), 1e-4);
    EXPECT_NEAR(plan.flight_travel_m.y(), flight.travel_m.y(), 1e-4);
    // crouch back by half the stroke, the stroke, the flight, the braking after touchdown
    const Eigen::Vector2d horizontal = plan.com_takeoff_velocity_m_s.head<2>();
    const Eigen::Vector2d braking = horizontal * horizontal.norm() / (2.0 * limits.landing_braking_m_s2);
    const Eigen::Vector2d total = 0.5 * plan.push_stroke_m.head<2>() + flight.travel_m + braking;
    EXPECT_NEAR(total.x(), target.displacement_m.x(), 1e-3);
    EXPECT_NEAR(total.y(), target.displacement_m.y(), 1e-3);
    EXPECT_NEAR(plan.planned_displacement_m.x(), target.displacement_m.x(), 1e-3);
    // the turn: a constant rate from the push's middle to touchdown
    EXPECT_NEAR(plan.yaw_rate_rad_s * (0.5 * plan.push_duration_s + flight.duration_s), target.yaw_rad, 1e-3);
    // the apex the flight reaches
    EXPECT_NEAR(plan.apex_height_m,
                plan.takeoff_height_m + std::pow(plan.com_takeoff_velocity_m_s.z(), 2) / (2.0 * kGravityMPerS2), 1e-9);
  }
}

TEST(JumpPlan, TheFlightTimeAndTheBrakingDistanceMatchTheArcAndTheDecelerationIntegratedStepByStep) {
  // what the controller places the feet with in the air, from the take-off the push gave
  for (const double vz : {1.2, 1.8, 2.4}) {
    for (const double drop_m : {-0.1, 0.0, 0.02, 0.12}) {
      const Flight flight = integrate_flight(Eigen::Vector3d(0.0, 0.0, vz), 0.0, -drop_m);
      EXPECT_NEAR(flight_time_s(vz, drop_m), flight.duration_s, 1e-5) << vz << " m/s, drop " << drop_m;
    }
  }
  const JumpLimits limits;
  constexpr double kDt = 1e-6;
  for (const Eigen::Vector2d& velocity : {Eigen::Vector2d(1.2, 0.0), Eigen::Vector2d(-0.3, 0.6)}) {
    // slow down at the landing's braking, along the velocity, until at rest
    Eigen::Vector2d v = velocity;
    Eigen::Vector2d travelled = Eigen::Vector2d::Zero();
    const Eigen::Vector2d deceleration = limits.landing_braking_m_s2 * velocity.normalized();
    while (v.dot(velocity) > 0.0) {
      travelled += v * kDt;
      v -= deceleration * kDt;
    }
    const Eigen::Vector2d braking = braking_distance(velocity, limits);
    EXPECT_NEAR(braking.x(), travelled.x(), 1e-5);
    EXPECT_NEAR(braking.y(), travelled.y(), 1e-5);
  }
}

TEST(JumpPlan, ThePushIsAConstantAccelerationFromTheCrouchToTheTakeoffHeight) {
  const JumpLimits limits;
  const JumpPlan plan = plan_jump(JumpTarget{{0.3, 0.1}, 0.5, 0.0, 0.0}, limits);
  const double t = plan.push_duration_s;
  // v = a t, s = a t^2 / 2, and the stroke rises from the crouch to the take-off height
  EXPECT_NEAR((plan.push_acceleration_m_s2 * t - plan.takeoff_velocity_m_s).norm(), 0.0, 1e-9);
  EXPECT_NEAR((0.5 * plan.push_acceleration_m_s2 * t * t - plan.push_stroke_m).norm(), 0.0, 1e-9);
  EXPECT_NEAR(plan.push_stroke_m.z(), limits.takeoff_height_m - limits.crouch_height_m, 1e-9);
  // the trunk's velocity carries the centre of mass's through the standing legs' momentum map
  EXPECT_NEAR((plan.momentum_map * plan.takeoff_velocity_m_s - plan.com_takeoff_velocity_m_s).norm(), 0.0, 1e-9);
  // the stroke is centred over the feet
  EXPECT_NEAR((plan.crouch_offset_m + 0.5 * plan.push_stroke_m.head<2>()).norm(), 0.0, 1e-12);
}

TEST(JumpPlan, AnUpJumpRisesToItsApexWhenTheLegsAllowIt) {
  JumpLimits limits;
  const JumpPlan plan = plan_jump(JumpTarget{{0.0, 0.0}, 0.0, 0.2, 0.0}, limits);
  EXPECT_EQ(plan.shortfall, kJumpReachable);
  EXPECT_NEAR(plan.apex_height_m, limits.stand_height_m + 0.2, 1e-9);
  // slower legs: the apex is what they reach, and the plan says why
  limits.max_takeoff_speed_m_s = 1.5;
  const JumpPlan slow = plan_jump(JumpTarget{{0.0, 0.0}, 0.0, 0.2, 0.0}, limits);
  EXPECT_EQ(slow.shortfall, kJumpSpeedLimited);
  EXPECT_NEAR(slow.com_takeoff_velocity_m_s.z(), 1.5, 1e-9);
  EXPECT_STREQ(jump_shortfall_text(slow.shortfall), "take-off speed");
}

TEST(JumpPlan, AJumpForHeightPushesFromTheDeeperCrouchToTheLowerTakeoffAndTheOthersFromTheStandardOnes) {
  const JumpLimits limits;
  const JumpPlan high = plan_jump(JumpTarget{{0.0, 0.0}, 0.0, 0.3, 0.0}, limits);
  EXPECT_EQ(high.crouch_height_m, limits.high_jump_crouch_height_m);
  EXPECT_EQ(high.takeoff_height_m, limits.high_jump_takeoff_height_m);
  EXPECT_NEAR(high.push_stroke_m.z(), limits.high_jump_takeoff_height_m - limits.high_jump_crouch_height_m, 1e-9);
  // the apex is still the asked one: the flight starts lower and faster
  EXPECT_NEAR(high.apex_height_m, limits.stand_height_m + 0.3, 1e-9);
  for (const JumpTarget& target : {JumpTarget{{0.6, 0.0}, 0.0, 0.0, 0.0}, JumpTarget{{0.0, 0.0}, 1.5, 0.0, 0.0}}) {
    const JumpPlan plan = plan_jump(target, limits);
    EXPECT_EQ(plan.crouch_height_m, limits.crouch_height_m);
    EXPECT_EQ(plan.takeoff_height_m, limits.takeoff_height_m);
  }
}

TEST(JumpPlan, ALongJumpFliesHigherBeforeItAsksMoreHorizontalSpeedThanTheLandingBrakes) {
  const JumpLimits limits;
  const JumpPlan plan = plan_jump(JumpTarget{{0.6, 0.0}, 0.0, 0.0, 0.0}, limits);
  EXPECT_LE(plan.com_takeoff_velocity_m_s.head<2>().norm(), limits.max_horizontal_speed_m_s + 1e-9);
  EXPECT_GT(plan.com_takeoff_velocity_m_s.z(), limits.min_vertical_speed_m_s);
  EXPECT_NEAR(plan.planned_displacement_m.x(), 0.6, 0.01);
  // too far for any flight the legs allow: the longest it can, and why
  const JumpPlan far = plan_jump(JumpTarget{{3.0, 0.0}, 0.0, 0.0, 0.0}, limits);
  EXPECT_TRUE(far.shortfall & kJumpLandingLimited);
  EXPECT_LT(far.planned_displacement_m.x(), 3.0);
  EXPECT_NEAR(far.com_takeoff_velocity_m_s.x(), limits.max_horizontal_speed_m_s, 1e-9);
}

TEST(JumpPlan, APushThatWouldSlipIsCutToTheFrictionCone) {
  JumpLimits limits;
  limits.friction_mu = 0.2;
  const JumpPlan plan = plan_jump(JumpTarget{{0.3, 0.0}, 0.0, 0.0, 0.0}, limits);
  EXPECT_TRUE(plan.shortfall & kJumpFrictionLimited);
  // the trunk's push: horizontal within mu of the vertical force's acceleration
  const Eigen::Vector3d& a = plan.push_acceleration_m_s2;
  EXPECT_LE(a.head<2>().norm(), limits.friction_mu * (a.z() + kGravityMPerS2) + 1e-9);
  EXPECT_LT(plan.planned_displacement_m.x(), 0.3);
}

TEST(JumpPlan, AForceJumpTakesTheAskedAccelerationWithinTheLimitsAndIgnoresNonFiniteValues) {
  const JumpLimits limits;
  const double stroke = limits.takeoff_height_m - limits.crouch_height_m;
  const JumpPlan plan = plan_force_jump(Eigen::Vector3d(2.0, 0.0, 12.0), 3.0, limits);
  EXPECT_EQ(plan.shortfall, kJumpReachable);
  // the centre of mass accelerates as asked through the push; the trunk carries it over the stroke
  const Eigen::Vector3d com_acceleration = plan.com_takeoff_velocity_m_s / plan.push_duration_s;
  EXPECT_NEAR(com_acceleration.z(), 12.0, 1e-6);
  EXPECT_NEAR(com_acceleration.x(), 2.0, 1e-6);
  EXPECT_NEAR(com_acceleration.y(), 0.0, 1e-6);
  EXPECT_NEAR(0.5 * plan.push_acceleration_m_s2.z() * plan.push_duration_s * plan.push_duration_s, stroke, 1e-9);
  EXPECT_NEAR(plan.yaw_rate_rad_s, 3.0 * plan.push_duration_s, 1e-9);
  // absurd: clamped to what the legs, the ground and the landing allow, and said so
  const JumpPlan absurd = plan_force_jump(Eigen::Vector3d(500.0, 0.0, 1e4), 1e3, limits);
  EXPECT_NE(absurd.shortfall, kJumpReachable);
  EXPECT_LE(absurd.com_takeoff_velocity_m_s.z(), limits.max_takeoff_speed_m_s + 1e-9);
  EXPECT_LE(absurd.com_takeoff_velocity_m_s.head<2>().norm(), limits.max_horizontal_speed_m_s + 1e-9);
  EXPECT_LE(std::abs(absurd.planned_yaw_rad), limits.max_turn_rad + 1e-9);
  // NaN and Inf count as nothing asked: the lowest hop, in place
  const double nan = std::nan("");
  const JumpPlan broken = plan_force_jump(Eigen::Vector3d(nan, INFINITY, nan), nan, limits);
  EXPECT_NEAR(broken.com_takeoff_velocity_m_s.z(), limits.min_vertical_speed_m_s, 1e-9);
  EXPECT_NEAR(broken.com_takeoff_velocity_m_s.head<2>().norm(), 0.0, 1e-12);
  EXPECT_EQ(broken.yaw_rate_rad_s, 0.0);
}

// MuJoCo's momentum of the whole model with the trunk moving at v (level, not turning) and each
// foot standing still: the joint rates -J^-1 v
struct SimMomentum {
  Eigen::Vector3d linear;
  Eigen::Vector3d angular;  // about the centre of mass, world axes
  double mass_kg;
};
SimMomentum simulator_momentum(const std::array<Eigen::Vector3d, kNumLegs>& leg_q, const Eigen::Vector3d& v) {
  MujocoBackend backend(testing::sim_config());
  const mjModel* model = backend.model();
  mjData* data = mj_makeData(model);
  static const char* const kJoints[kNumJoints] = {"FR_abad", "FR_hip", "FR_knee", "FL_abad", "FL_hip", "FL_knee",
                                                  "RR_abad", "RR_hip", "RR_knee", "RL_abad", "RL_hip", "RL_knee"};
  mju_zero(data->qvel, model->nv);
  data->qpos[2] = 0.3;
  data->qpos[3] = 1.0;
  data->qpos[4] = data->qpos[5] = data->qpos[6] = 0.0;
  for (int k = 0; k < 3; ++k) data->qvel[k] = v[k];
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
    const Eigen::Vector3d qd = -foot_jacobian(leg, leg_q[leg]).inverse() * v;
    for (std::size_t k = 0; k < kJointsPerLeg; ++k) {
      const int joint = mj_name2id(model, mjOBJ_JOINT, kJoints[kJointsPerLeg * leg + k]);
      data->qpos[model->jnt_qposadr[joint]] = leg_q[leg][static_cast<Eigen::Index>(k)];
      data->qvel[model->jnt_dofadr[joint]] = qd[static_cast<Eigen::Index>(k)];
    }
  }
  mj_forward(model, data);
  mj_subtreeVel(model, data);
  const int trunk = mj_name2id(model, mjOBJ_BODY, "trunk");
  SimMomentum m;
  m.mass_kg = model->body_subtreemass[trunk];
  m.linear = m.mass_kg * Eigen::Vector3d(data->subtree_linvel[3 * trunk], data->subtree_linvel[3 * trunk + 1],
                                         data->subtree_linvel[3 * trunk + 2]);
  m.angular = Eigen::Vector3d(data->subtree_angmom[3 * trunk], data->subtree_angmom[3 * trunk + 1],
                              data->subtree_angmom[3 * trunk + 2]);
  mj_deleteData(data);
  return m;
}

TEST(JumpPlan, TheStandingLegsMomentumMatchesTheSimulatorsForTheSameModel) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> height(0.14, 0.27), speed(-2.0, 2.0), reach(-0.05, 0.05);
  for (int trial = 0; trial < 10; ++trial) {
    // the feet somewhere below the hips, the trunk at some height, moving some way
    std::array<Eigen::Vector3d, kNumLegs> q{};
    const double h = height(rng);
    for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
      Eigen::Vector3d foot = foot_position_in_body(leg, Eigen::Vector3d(0.0, 0.8, -1.5));
      foot += Eigen::Vector3d(reach(rng), reach(rng), 0.0);
      foot.z() = -h;
      q[leg] = inverse_kinematics_in_body(leg, foot).q;
    }
    const Eigen::Vector3d v(speed(rng), speed(rng), speed(rng));
    const SimMomentum sim = simulator_momentum(q, v);
    EXPECT_NEAR(sim.mass_kg, robot::kTotalMassKg, 0.01);
    const Eigen::Vector3d ours = robot::kTotalMassKg * (standing_momentum_map(q, robot::kTotalMassKg) * v);
    EXPECT_LT((ours - sim.linear).norm(), 0.01 * sim.linear.norm() + 1e-3) << "trial " << trial;
    // angular: the links' spin taken about the body's axes, products of inertia left out: within
    // 0.03 N m s of the simulator's (a jump's push carries about 0.3)
    const Eigen::Vector3d angular = standing_angular_momentum(q, v, robot::kTotalMassKg);
    EXPECT_LT((angular - sim.angular).norm(), 0.03)
        << "trial " << trial << ": " << angular.transpose() << " vs " << sim.angular.transpose();
  }
}

}  // namespace
}  // namespace cerebellum
