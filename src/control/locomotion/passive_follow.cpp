#include "control/locomotion/passive_follow.hpp"

#include <algorithm>
#include <cmath>

#include "core/joint_layout.hpp"
#include "core/leg_kinematics.hpp"

namespace cerebellum {

Eigen::Vector2d external_force_world(const RobotState& state, double mass_kg) {
  const Eigen::Matrix3d body_to_world = state.orientation.toRotationMatrix();
  Eigen::Vector3d ground = Eigen::Vector3d::Zero();
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
    if (state.contact[leg] < 0.5) continue;
    const Eigen::Vector3d q(state.q[3 * leg], state.q[3 * leg + 1], state.q[3 * leg + 2]);
    const Eigen::Vector3d tau(state.tau[3 * leg], state.tau[3 * leg + 1], state.tau[3 * leg + 2]);
    // the ground's force on the foot balances the leg's torques: tau = -J^T f (zero when singular)
    ground -= body_to_world * foot_force_from_torque(foot_jacobian(leg, q), tau);
  }
  const Eigen::Vector3d external = mass_kg * state.accel_world - ground;
  return external.head<2>();
}

void PassiveFollow::reset() {
  force_.setZero();
  filtered_.setZero();
  bias_.setZero();
  velocity_.setZero();
  following_ = false;
  pulled_s_ = 0.0;
  quiet_s_ = 0.0;
}

Eigen::Vector2d PassiveFollow::update(const RobotState& state, double dt_s) {
  const Eigen::Vector2d raw = external_force_world(state, config_.mass_kg);
  if (!raw.allFinite()) return velocity_;
  filtered_ += (raw - filtered_) * std::min(1.0, dt_s / config_.force_filter_s);
  // only what stays inside the deadband is learnt: a pull is never taken for an error
  if (!following_ && (filtered_ - bias_).norm() < config_.deadband_n) {
    bias_ += (filtered_ - bias_) * std::min(1.0, dt_s / config_.bias_time_constant_s);
  }
  force_ = filtered_ - bias_;

  // the force beyond the deadband drives the admittance
  const double magnitude = force_.norm();
  const Eigen::Vector2d drive = magnitude > config_.deadband_n
                                    ? Eigen::Vector2d(force_ * (1.0 - config_.deadband_n / magnitude))
                                    : Eigen::Vector2d::Zero();

  if (!following_) {
    pulled_s_ = magnitude > config_.start_force_n ? pulled_s_ + dt_s : 0.0;
    if (pulled_s_ >= config_.start_hold_s) {
      following_ = true;
      quiet_s_ = 0.0;
    }
  }
  if (following_) {
    velocity_ += (drive - config_.damping_n_s_per_m * velocity_) * (dt_s / config_.virtual_mass_kg);
    const bool quiet = magnitude < config_.start_force_n && velocity_.norm() < config_.stop_speed_m_s;
    quiet_s_ = quiet ? quiet_s_ + dt_s : 0.0;
    if (quiet_s_ >= config_.stop_hold_s) {
      following_ = false;
      pulled_s_ = 0.0;
      velocity_.setZero();
    }
  }
  return velocity_;
}

}  // namespace cerebellum
