// Roll, pitch, yaw against Eigen's own rotation built from the angles (round trips), and the
// clamp that keeps pitch finite at gimbal lock.
#include "core/orientation.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/robot_model.hpp"

namespace cerebellum {
namespace {

Eigen::Quaterniond from_rpy(double roll, double pitch, double yaw) {
  return Eigen::Quaterniond(Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()) *
                            Eigen::AngleAxisd(pitch, Eigen::Vector3d::UnitY()) *
                            Eigen::AngleAxisd(roll, Eigen::Vector3d::UnitX()));
}

TEST(Orientation, RollPitchYawInvertTheZyxComposition) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> angle(-3.1, 3.1);
  std::uniform_real_distribution<double> pitch_angle(-1.55, 1.55);
  for (int i = 0; i < 500; ++i) {
    const double roll = angle(rng);
    const double pitch = pitch_angle(rng);
    const double yaw = angle(rng);
    const Eigen::Vector3d rpy = rpy_from_quaternion(from_rpy(roll, pitch, yaw));
    EXPECT_NEAR(rpy.x(), roll, 1e-9);
    EXPECT_NEAR(rpy.y(), pitch, 1e-9);
    EXPECT_NEAR(rpy.z(), yaw, 1e-9);
  }
}

TEST(Orientation, AnglesOfARandomRotationRebuildTheSameRotation) {
  // any unit quaternion, also q and -q, which are the same rotation
  std::mt19937 rng(11);
  std::normal_distribution<double> unit(0.0, 1.0);
  for (int i = 0; i < 500; ++i) {
    const Eigen::Quaterniond q = Eigen::Quaterniond(unit(rng), unit(rng), unit(rng), unit(rng)).normalized();
    const Eigen::Vector3d rpy = rpy_from_quaternion(q);
    EXPECT_LE(std::abs(rpy.y()), robot::kPi / 2);
    const Eigen::Matrix3d rebuilt = from_rpy(rpy.x(), rpy.y(), rpy.z()).toRotationMatrix();
    EXPECT_TRUE(rebuilt.isApprox(q.toRotationMatrix(), 1e-9)) << i;
    const Eigen::Vector3d negated = rpy_from_quaternion(Eigen::Quaterniond(-q.w(), -q.x(), -q.y(), -q.z()));
    EXPECT_TRUE(negated.isApprox(rpy, 1e-12)) << i;
  }
}

TEST(Orientation, NearGimbalLockTheRotationStillRoundTrips) {
  std::mt19937 rng(13);
  std::uniform_real_distribution<double> angle(-3.0, 3.0);
  for (double pitch : {robot::kPi / 2 - 1e-4, -(robot::kPi / 2 - 1e-4)}) {
    for (int i = 0; i < 100; ++i) {
      const Eigen::Quaterniond q = from_rpy(angle(rng), pitch, angle(rng));
      const Eigen::Vector3d rpy = rpy_from_quaternion(q);
      EXPECT_NEAR(rpy.y(), pitch, 1e-6);
      // roll and yaw are badly conditioned here one by one, the rotation they make is not
      EXPECT_TRUE(from_rpy(rpy.x(), rpy.y(), rpy.z()).toRotationMatrix().isApprox(q.toRotationMatrix(), 1e-6));
    }
  }
}

TEST(Orientation, PitchStaysFiniteWhenRoundingPushesItsSinePastOne) {
  // exactly nose up (pitch = +-pi/2) and a quaternion a little longer than unit: 2 (w y - z x) > 1
  for (double sign : {1.0, -1.0}) {
    const double c = std::sqrt(0.5) * (1.0 + 1e-9);
    const Eigen::Quaterniond q(c, 0.0, sign * c, 0.0);
    ASSERT_GT(std::abs(2.0 * (q.w() * q.y() - q.z() * q.x())), 1.0);
    const Eigen::Vector3d rpy = rpy_from_quaternion(q);
    EXPECT_TRUE(rpy.allFinite());
    EXPECT_DOUBLE_EQ(rpy.y(), sign * robot::kPi / 2);
  }
}

}  // namespace
}  // namespace cerebellum
