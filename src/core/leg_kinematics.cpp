#include "core/leg_kinematics.hpp"

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <algorithm>
#include <cmath>

#include "core/joint_layout.hpp"
#include "core/robot_model.hpp"

namespace cerebellum {
namespace {

using robot::kAbadLength;
using robot::kShankLength;
using robot::kThighLength;

constexpr double kSingularDeterminant = 1e-9;

// the sagittal-plane part of the leg before the abad rotation: x forward, z' down the leg
struct SagittalPoint {
  double x;
  double z;
};

SagittalPoint sagittal_foot(double hip, double knee) {
  return {-kThighLength * std::sin(hip) - kShankLength * std::sin(hip + knee),
          -kThighLength * std::cos(hip) - kShankLength * std::cos(hip + knee)};
}

}  // namespace

Vec3 hip_position(std::size_t leg) {
  return {is_front_leg(leg) ? robot::kHipX : -robot::kHipX, leg_side_sign(leg) * robot::kHipY, 0.0};
}

Vec3 foot_position_in_hip(std::size_t leg, const Vec3& q) {
  const double lateral = leg_side_sign(leg) * kAbadLength;
  const SagittalPoint s = sagittal_foot(q[1], q[2]);
  const double c0 = std::cos(q[0]);
  const double s0 = std::sin(q[0]);
  // rotate (x, lateral, z') about x by the abad angle
  return {s.x, c0 * lateral - s0 * s.z, s0 * lateral + c0 * s.z};
}

Vec3 foot_position_in_body(std::size_t leg, const Vec3& q) { return hip_position(leg) + foot_position_in_hip(leg, q); }

Mat3 foot_jacobian(std::size_t leg, const Vec3& q) {
  const double lateral = leg_side_sign(leg) * kAbadLength;
  const double c0 = std::cos(q[0]);
  const double s0 = std::sin(q[0]);
  const double c1 = std::cos(q[1]);
  const double s1 = std::sin(q[1]);
  const double c12 = std::cos(q[1] + q[2]);
  const double s12 = std::sin(q[1] + q[2]);
  const SagittalPoint s = sagittal_foot(q[1], q[2]);
  // derivatives of the sagittal point
  const double dx_dhip = -kThighLength * c1 - kShankLength * c12;
  const double dx_dknee = -kShankLength * c12;
  const double dz_dhip = kThighLength * s1 + kShankLength * s12;
  const double dz_dknee = kShankLength * s12;
  Mat3 j;
  j << 0.0, dx_dhip, dx_dknee, -s0 * lateral - c0 * s.z, -s0 * dz_dhip, -s0 * dz_dknee, c0 * lateral - s0 * s.z,
      c0 * dz_dhip, c0 * dz_dknee;
  return j;
}

Vec3 foot_force_from_torque(const Mat3& jacobian, const Vec3& tau) {
  if (std::abs(jacobian.determinant()) <= kSingularDeterminant) return Vec3::Zero();
  return jacobian.transpose().inverse() * tau;
}

LegIkResult inverse_kinematics_in_hip(std::size_t leg, const Vec3& p) {
  const double lateral = leg_side_sign(leg) * kAbadLength;
  bool reachable = true;

  // abad: the foot's (y, z) is the rotated (lateral, z'); the leg hangs below, z' < 0
  const double yz_sq = p.y() * p.y() + p.z() * p.z();
  double z_sag_sq = yz_sq - lateral * lateral;
  if (z_sag_sq < 1e-12) {
    reachable = false;
    z_sag_sq = 1e-12;
  }
  const double z_sag = -std::sqrt(z_sag_sq);
  const double abad = std::atan2(p.z(), p.y()) - std::atan2(z_sag, lateral);

  const SagittalIkResult sagittal = sagittal_inverse_kinematics(p.x(), z_sag);
  // keep the abad angle in (-pi, pi]
  return {Vec3(std::remainder(abad, 2.0 * robot::kPi), sagittal.hip, sagittal.knee), reachable && sagittal.reachable};
}

SagittalIkResult sagittal_inverse_kinematics(double x, double z) {
  // knee from the distance hip-to-foot (law of cosines)
  bool reachable = true;
  double cos_knee =
      (x * x + z * z - kThighLength * kThighLength - kShankLength * kShankLength) / (2.0 * kThighLength * kShankLength);
  if (cos_knee > 1.0 || cos_knee < -1.0) {
    reachable = false;
    cos_knee = std::clamp(cos_knee, -1.0, 1.0);
  }
  const double knee = -std::acos(cos_knee);
  // hip: direction of the foot from the hip minus the knee's contribution
  const double hip =
      std::atan2(-x, -z) - std::atan2(kShankLength * std::sin(knee), kThighLength + kShankLength * std::cos(knee));
  return {hip, knee, reachable};
}

LegIkResult inverse_kinematics_in_body(std::size_t leg, const Vec3& p) {
  return inverse_kinematics_in_hip(leg, p - hip_position(leg));
}

Vec3 shank_angular_velocity_body(const Vec3& omega_body, const Vec3& q, const Vec3& qd) {
  return omega_body + Vec3(qd[0], 0.0, 0.0) + (qd[1] + qd[2]) * Vec3(0.0, std::cos(q[0]), std::sin(q[0]));
}

Vec3 trunk_velocity_over_rolling_foot(std::size_t leg, const Mat3& body_to_world, const Vec3& omega_body, const Vec3& q,
                                      const Vec3& qd) {
  const Vec3 radius_up(0.0, 0.0, robot::kFootRadius);
  const Vec3 foot_centre_velocity_body = foot_jacobian(leg, q) * qd + omega_body.cross(foot_position_in_body(leg, q));
  const Vec3 rolling_world = (body_to_world * shank_angular_velocity_body(omega_body, q, qd)).cross(radius_up);
  return rolling_world - body_to_world * foot_centre_velocity_body;
}

}  // namespace cerebellum
