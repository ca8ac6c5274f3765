// Leg kinematics against independent checks: finite differences, round trips, hand-computed poses.
#include "core/leg_kinematics.hpp"

#include <gtest/gtest.h>

#include <Eigen/LU>
#include <random>

#include "core/robot_model.hpp"

namespace cerebellum {
namespace {

Vec3 random_joint_angles(std::mt19937& rng, std::size_t leg) {
  // stay well inside the ranges where the knee is bent (IK picks the knee-back branch)
  std::uniform_real_distribution<double> abad(-0.6, 0.6);
  std::uniform_real_distribution<double> hip(is_front_leg(leg) ? -1.2 : -0.9, 2.5);
  std::uniform_real_distribution<double> knee(-2.5, -0.3);
  return {abad(rng), hip(rng), knee(rng)};
}

TEST(LegKinematics, StandPoseFootIsBelowTheHipAtHandComputedPosition) {
  const Vec3 q(robot::kStandPose[0], robot::kStandPose[1], robot::kStandPose[2]);
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
    const Vec3 p = foot_position_in_hip(leg, q);
    // hip 45 deg, knee -70 deg: the shank points 25 deg forward of vertical
    const double x = -0.12 * std::sin(robot::deg(45)) + 0.17391 * std::sin(robot::deg(25));
    const double z = -0.12 * std::cos(robot::deg(45)) - 0.17391 * std::cos(robot::deg(25));
    EXPECT_NEAR(p.x(), x, 1e-12);
    EXPECT_NEAR(p.y(), leg_side_sign(leg) * 0.094, 1e-12);
    EXPECT_NEAR(p.z(), z, 1e-12);
  }
}

TEST(LegKinematics, PositiveAbadSwingsTheFootTowardPositiveY) {
  // right-hand rule about +x: a leg hanging down moves to +y when abad turns positive
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
    const Vec3 straight(0.0, 0.0, -0.5);
    const Vec3 turned(0.3, 0.0, -0.5);
    EXPECT_GT(foot_position_in_hip(leg, turned).y(), foot_position_in_hip(leg, straight).y());
  }
}

TEST(LegKinematics, BodyFrameAddsTheHipOffsetsWithTheirSigns) {
  EXPECT_TRUE(hip_position(0).isApprox(Vec3(0.164, -0.042, 0.0)));
  EXPECT_TRUE(hip_position(1).isApprox(Vec3(0.164, 0.042, 0.0)));
  EXPECT_TRUE(hip_position(2).isApprox(Vec3(-0.164, -0.042, 0.0)));
  EXPECT_TRUE(hip_position(3).isApprox(Vec3(-0.164, 0.042, 0.0)));
}

TEST(LegKinematics, JacobianMatchesCentralFiniteDifferencesForEveryLeg) {
  std::mt19937 rng(7);
  const double h = 1e-6;
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
    for (int trial = 0; trial < 200; ++trial) {
      const Vec3 q = random_joint_angles(rng, leg);
      const Mat3 analytic = foot_jacobian(leg, q);
      for (int j = 0; j < 3; ++j) {
        Vec3 plus = q;
        Vec3 minus = q;
        plus[j] += h;
        minus[j] -= h;
        const Vec3 numeric = (foot_position_in_body(leg, plus) - foot_position_in_body(leg, minus)) / (2 * h);
        EXPECT_LT((analytic.col(j) - numeric).norm(), 1e-8) << "leg " << leg << " joint " << j;
      }
    }
  }
}

TEST(LegKinematics, InverseOfForwardGivesBackTheJointAnglesForEveryLeg) {
  std::mt19937 rng(11);
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
    int checked = 0;
    while (checked < 500) {
      const Vec3 q = random_joint_angles(rng, leg);
      // IK returns the branch with the foot below the abad axis; skip poses with the foot above it
      const double sagittal_z = -robot::kThighLength * std::cos(q[1]) - robot::kShankLength * std::cos(q[1] + q[2]);
      if (sagittal_z > -0.02) continue;
      ++checked;
      const LegIkResult ik = inverse_kinematics_in_body(leg, foot_position_in_body(leg, q));
      ASSERT_TRUE(ik.reachable);
      EXPECT_LT((ik.q - q).norm(), 1e-9) << "leg " << leg << " q " << q.transpose();
    }
  }
}

TEST(LegKinematics, ForwardOfInverseReachesWorkspaceTargets) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> dx(-0.08, 0.08);
  std::uniform_real_distribution<double> dy(-0.03, 0.03);
  std::uniform_real_distribution<double> dz(-0.25, -0.12);
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
    for (int trial = 0; trial < 500; ++trial) {
      const Vec3 target(dx(rng), leg_side_sign(leg) * robot::kAbadLength + dy(rng), dz(rng));
      const LegIkResult ik = inverse_kinematics_in_hip(leg, target);
      ASSERT_TRUE(ik.reachable) << target.transpose();
      EXPECT_LT((foot_position_in_hip(leg, ik.q) - target).norm(), 1e-9);
      EXPECT_LT(ik.q[2], 0.0) << "knee must bend backwards";
    }
  }
}

TEST(LegKinematics, UnreachableTargetIsReportedAndClampedToTheStretchedLeg) {
  const Vec3 far_below(0.0, -robot::kAbadLength, -1.0);
  const LegIkResult ik = inverse_kinematics_in_hip(0, far_below);
  EXPECT_FALSE(ik.reachable);
  EXPECT_NEAR(ik.q[2], 0.0, 1e-9);  // fully stretched
  EXPECT_NEAR(foot_position_in_hip(0, ik.q).z(), -(robot::kThighLength + robot::kShankLength), 1e-9);
}

TEST(FootForce, BalancesTheJointTorquesByVirtualWork) {
  // tau = J^T f, and the work f . dp of a small joint motion dq equals tau . dq, with dp taken
  // from forward kinematics (central difference), not from the Jacobian
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> torque(-12.0, 12.0);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
    for (int trial = 0; trial < 200; ++trial) {
      const Vec3 q = random_joint_angles(rng, leg);
      const Vec3 tau(torque(rng), torque(rng), torque(rng));
      const Mat3 jacobian = foot_jacobian(leg, q);
      if (std::abs(jacobian.determinant()) < 1e-4) continue;  // too close to singular to compare
      const Vec3 force = foot_force_from_torque(jacobian, tau);
      EXPECT_LT((jacobian.transpose() * force - tau).norm(), 1e-9 * (1.0 + tau.norm()));
      const Vec3 dq(unit(rng), unit(rng), unit(rng));
      const double h = 1e-6;
      const Vec3 dp = (foot_position_in_hip(leg, q + h * dq) - foot_position_in_hip(leg, q - h * dq)) / (2.0 * h);
      EXPECT_NEAR(force.dot(dp), tau.dot(dq), 1e-6 * (1.0 + force.norm())) << q.transpose();
    }
  }
}

TEST(FootForce, IsZeroForAStretchedLegWhoseJacobianIsSingular) {
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
    const Vec3 stretched(0.2, 0.4, 0.0);  // knee straight: hip and knee move the foot along one line
    EXPECT_EQ(foot_force_from_torque(foot_jacobian(leg, stretched), Vec3(1.0, 2.0, 3.0)), Vec3::Zero());
  }
}

}  // namespace
}  // namespace cerebellum
