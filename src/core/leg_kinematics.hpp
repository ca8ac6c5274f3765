// Leg kinematics of the CyberDog2-class leg in the SDK joint convention.
// Frames: "hip frame" = body axes with origin at the leg's abad joint; "body frame" = trunk frame.
#pragma once

#include <Eigen/Core>
#include <cstddef>

#include "core/joint_layout.hpp"

namespace cerebellum {

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;

struct LegIkResult {
  Vec3 q;          // abad, hip, knee (rad)
  bool reachable;  // false: the target was out of reach and q points at the nearest reachable foot
};

// one leg's three values (abad, hip, knee) of a joint array
inline Vec3 leg_vector(const JointArray<double>& values, std::size_t leg) {
  const std::size_t j = kJointsPerLeg * leg;
  return {values[j], values[j + 1], values[j + 2]};
}

// position of the abad joint in the body frame
Vec3 hip_position(std::size_t leg);

// foot centre relative to the abad joint (hip frame)
Vec3 foot_position_in_hip(std::size_t leg, const Vec3& q);
Vec3 foot_position_in_body(std::size_t leg, const Vec3& q);

// d(foot position)/dq, the same in hip and body frames
Mat3 foot_jacobian(std::size_t leg, const Vec3& q);

// the force f on the foot that joint torques tau balance in statics: tau = J^T f, f = J^-T tau;
// zero when the leg is singular (|det J| <= 1e-9, e.g. stretched straight: no unique force)
Vec3 foot_force_from_torque(const Mat3& jacobian, const Vec3& tau);

// angular velocity of a shank in the body frame: trunk rate, abad about x, hip + knee about the
// y axis turned by the abad angle
Vec3 shank_angular_velocity_body(const Vec3& omega_body, const Vec3& q, const Vec3& qd);

// the trunk's velocity (world) while the foot rolls on the ground without slipping: its contact
// point is still, its centre moves at omega_shank x (radius up), and the trunk moves opposite to
// the foot centre as seen from it: v = omega_shank x r_up - R (J qd + omega x foot)
Vec3 trunk_velocity_over_rolling_foot(std::size_t leg, const Mat3& body_to_world, const Vec3& omega_body, const Vec3& q,
                                      const Vec3& qd);

// hip and knee (knee bent backwards) that put the foot centre at (x, z) from the hip joint in the
// leg's sagittal plane, body axes; reachable false when (x, z) is beyond the leg (then the nearest)
struct SagittalIkResult {
  double hip;
  double knee;
  bool reachable;
};
SagittalIkResult sagittal_inverse_kinematics(double x, double z);

// joint angles that put the foot at p (hip frame), on the branch a standing robot uses: foot below
// the abad axis in the leg plane, knee bent backwards (knee < 0)
LegIkResult inverse_kinematics_in_hip(std::size_t leg, const Vec3& p);
LegIkResult inverse_kinematics_in_body(std::size_t leg, const Vec3& p);

}  // namespace cerebellum
