#include "control/upright/upright_state.hpp"

#include <cmath>

#include "core/leg_kinematics.hpp"
#include "core/robot_model.hpp"

namespace cerebellum {

Eigen::Quaterniond upright_orientation(const UprightPosition& position) {
  return Eigen::Quaterniond(position[3], position[4], position[5], position[6]).normalized();
}

double hind_shank_roll_angle(const Eigen::Matrix3d& trunk_to_world, const JointArray<double>& q) {
  double sum = 0.0;
  for (std::size_t leg = 2; leg < kNumLegs; ++leg) {
    const Eigen::Matrix3d shank = trunk_to_world * Eigen::AngleAxisd(q[3 * leg], Eigen::Vector3d::UnitX()) *
                                  Eigen::AngleAxisd(q[3 * leg + 1] + q[3 * leg + 2], Eigen::Vector3d::UnitY());
    sum += std::atan2(shank(0, 2), shank(2, 2));
  }
  return 0.5 * sum;
}

UprightState upright_state(const RobotState& state, double heading_yaw_rad, double rolling_origin_rad,
                           double feet_height_m) {
  const Eigen::Quaterniond heading(Eigen::AngleAxisd(-heading_yaw_rad, Eigen::Vector3d::UnitZ()));
  const Eigen::Quaterniond orientation = (heading * state.orientation).normalized();
  const Eigen::Matrix3d r = orientation.toRotationMatrix();
  // the hind feet stand (rolling, not slipping): the trunk is where their kinematics put it
  Eigen::Vector3d feet_body = Eigen::Vector3d::Zero();
  Eigen::Vector3d velocity_world = Eigen::Vector3d::Zero();
  for (std::size_t leg = 2; leg < kNumLegs; ++leg) {
    const Vec3 q(state.q[3 * leg], state.q[3 * leg + 1], state.q[3 * leg + 2]);
    const Vec3 qd(state.qd[3 * leg], state.qd[3 * leg + 1], state.qd[3 * leg + 2]);
    feet_body += 0.5 * foot_position_in_body(leg, q);
    velocity_world += 0.5 * trunk_velocity_over_rolling_foot(leg, r, state.omega_body, q, qd);
  }
  UprightState out;
  // the contact points stay put; the foot centres roll forward with the shanks' turn
  const Eigen::Vector3d feet_world(robot::kFootRadius * (hind_shank_roll_angle(r, state.q) - rolling_origin_rad), 0.0,
                                   feet_height_m);
  out.position.head<3>() = feet_world - r * feet_body;
  out.position.segment<4>(3) << orientation.w(), orientation.x(), orientation.y(), orientation.z();
  out.velocity.segment<3>(3) = state.omega_body;
  for (std::size_t j = 0; j < kNumJoints; ++j) {
    out.position[7 + j] = state.q[j];
    out.velocity[6 + j] = state.qd[j];
  }
  // the balance's gain weighs this velocity heavily (the contacts' stiff direction): leaving out
  // the feet's rolling (a few mm/s) made the rise unstable
  out.velocity.head<3>() = velocity_world;
  return out;
}

UprightVelocity upright_difference(const UprightPosition& from, const UprightPosition& to) {
  UprightVelocity d;
  d.head<3>() = to.head<3>() - from.head<3>();
  Eigen::Quaterniond turn = upright_orientation(from).conjugate() * upright_orientation(to);
  if (turn.w() < 0.0) turn.coeffs() = -turn.coeffs();
  const double sin_half = turn.vec().norm();
  d.segment<3>(3) = sin_half < 1e-12 ? Eigen::Vector3d(2.0 * turn.vec())
                                     : Eigen::Vector3d(turn.vec() * (2.0 * std::atan2(sin_half, turn.w()) / sin_half));
  d.tail<kNumJoints>() = to.tail<kNumJoints>() - from.tail<kNumJoints>();
  return d;
}

}  // namespace cerebellum
