#include "control/balance_controller.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>

#include "control/leg_gravity.hpp"
#include "core/leg_kinematics.hpp"
#include "core/robot_model.hpp"

namespace cerebellum {
namespace {

using robot::kGravityMPerS2;

// world angular velocity of ZYX angles changing at rpy_rate
Eigen::Vector3d angular_velocity_from_rpy_rate(const Eigen::Vector3d& rpy, const Eigen::Vector3d& rpy_rate) {
  const double cp = std::cos(rpy.y()), sp = std::sin(rpy.y()), cy = std::cos(rpy.z()), sy = std::sin(rpy.z());
  Eigen::Matrix3d map;
  map << cy * cp, -sy, 0.0, sy * cp, cy, 0.0, -sp, 0.0, 1.0;
  return map * rpy_rate;
}

Eigen::Vector3d clamp_norm(const Eigen::Vector3d& v, double max_norm) {
  const double norm = v.norm();
  return norm > max_norm ? Eigen::Vector3d(v * (max_norm / norm)) : v;
}

}  // namespace

Vector6d gravity_wrench(double mass_kg) {
  Vector6d w = Vector6d::Zero();
  w(2) = mass_kg * kGravityMPerS2;
  return w;
}

BalanceController::BalanceController(const BalanceConfig& config)
    : config_(config), distribution_(config.distribution), trim_(config.trim) {}

void BalanceController::start(const RobotState& state) {
  frame_.anchor(state);
  was_in_air_ = {};
  estimated_pose_ = frame_.anchored_pose();
  estimated_velocity_.setZero();
  for (Eigen::Vector3d& force : forces_) force.setZero();
  height_integral_ = 0.0;
  angle_integral_.setZero();
  trim_.reset();
}

Eigen::Vector2d BalanceController::body_xy_for_com(const Eigen::Vector2d& com_xy, const Eigen::Vector3d& rpy) const {
  return com_xy - (rotation_from_rpy(rpy) * config_.com_in_body).head<2>();
}

void BalanceController::compute(const RobotState& state, const BalanceTarget& target, double dt_s,
                                JointCommand& command) {
  const Eigen::Matrix3d rotation = frame_.body_rotation(state);

  // a leg that has just been put down stands where its foot is now
  LegMask stance{};
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
    stance[leg] = !target.in_air[leg];
    if (was_in_air_[leg] && stance[leg]) {
      frame_.set_foothold(leg, estimated_pose_.position + rotation * state.foot_position_body[leg]);
    }
    was_in_air_[leg] = target.in_air[leg];
  }
  estimated_pose_.rpy = frame_.body_rpy(state);
  frame_.estimate(state, stance, estimated_pose_.position, estimated_velocity_);
  const Eigen::Vector3d omega = frame_.angular_velocity(state);

  // desired wrench about the centre of mass
  const Eigen::Vector3d position_error = target.pose.position - estimated_pose_.position;
  const Eigen::Vector3d velocity_error = target.rate.position - estimated_velocity_;
  Eigen::Vector3d acceleration =
      config_.kp_position.cwiseProduct(position_error) + config_.kd_position.cwiseProduct(velocity_error);
  if (!target.hold_position_xy) {
    acceleration.head<2>() = -config_.kd_position.head<2>().cwiseProduct(estimated_velocity_.head<2>());
  }
  acceleration.head<2>() =
      clamp_norm(Eigen::Vector3d(acceleration.x(), acceleration.y(), 0.0), config_.max_position_acceleration).head<2>();
  if (std::abs(position_error.z()) < config_.integrate_below_height_error_m) {
    height_integral_ = std::clamp(height_integral_ + dt_s * config_.ki_height * position_error.z(),
                                  -config_.max_integral_height_acceleration, config_.max_integral_height_acceleration);
  }
  acceleration.z() += height_integral_;
  const Eigen::Matrix3d rotation_des = rotation_from_rpy(target.pose.rpy);
  const Eigen::Vector3d angle_error = rotation_error(rotation_des, rotation);
  if (angle_error.norm() < config_.integrate_below_angle_error_rad) {
    angle_integral_ = (angle_integral_ + dt_s * config_.ki_orientation.cwiseProduct(angle_error))
                          .cwiseMax(-config_.max_integral_angular_acceleration)
                          .cwiseMin(config_.max_integral_angular_acceleration);
  }
  const Eigen::Vector3d omega_des = angular_velocity_from_rpy_rate(target.pose.rpy, target.rate.rpy);
  const Eigen::Vector3d angular_acceleration = clamp_norm(config_.kp_orientation.cwiseProduct(angle_error) +
                                                              config_.kd_orientation.cwiseProduct(omega_des - omega),
                                                          config_.max_tilt_acceleration) +
                                               angle_integral_;
  const Eigen::Matrix3d inertia = rotation * config_.inertia_diag.asDiagonal() * rotation.transpose();
  wrench_.head<3>() = config_.mass_kg * (acceleration + Eigen::Vector3d(0.0, 0.0, kGravityMPerS2));
  wrench_.tail<3>() = inertia * angular_acceleration;

  // share it among the loaded feet
  std::array<double, kNumLegs> force_limit{};
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) force_limit[leg] = stance[leg] ? target.force_z_max_n[leg] : 0.0;
  if (distribution_.solve(feet_from_com(state, rotation, config_.com_in_body), force_limit, wrench_, solved_forces_) ==
      qp::QpStatus::Solved) {
    forces_ = solved_forces_;
  }

  // joints: forces on loaded legs, foot targets on legs in the air; every leg holds its own weight
  const Eigen::Matrix3d rotation_legs = rotation_from_rpy(trim_.update(target.pose.rpy, estimated_pose_.rpy, dt_s));
  // without position hold the joints follow the body where a push has left it
  Eigen::Vector3d body_for_legs = target.pose.position;
  if (!target.hold_position_xy) body_for_legs.head<2>() = estimated_pose_.position.head<2>();
  const Eigen::Vector3d gravity_body = state.orientation.conjugate() * Eigen::Vector3d(0.0, 0.0, -kGravityMPerS2);
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
    const std::size_t j = kJointsPerLeg * leg;
    const Vec3 q(state.q[j], state.q[j + 1], state.q[j + 2]);
    Vec3 tau = leg_gravity_torque(leg, q, gravity_body);
    if (stance[leg]) tau -= foot_jacobian(leg, q).transpose() * (rotation.transpose() * forces_[leg]);
    // the foot where the target puts it, seen from the desired body pose
    const Eigen::Vector3d foot = stance[leg] ? frame_.foothold(leg) : target.swing_foot[leg];
    const LegIkResult ik = inverse_kinematics_in_body(leg, rotation_legs.transpose() * (foot - body_for_legs));
    for (std::size_t k = 0; k < kJointsPerLeg; ++k) {
      const Eigen::Index e = static_cast<Eigen::Index>(k);
      command.q_des[j + k] = ik.q[e];
      command.qd_des[j + k] = 0.0;
      command.kp[j + k] = stance[leg] ? config_.stance_kp : config_.swing_kp;
      command.kd[j + k] = stance[leg] ? config_.stance_kd : config_.swing_kd;
      command.tau_ff[j + k] = tau[e];
    }
  }
}

}  // namespace cerebellum
