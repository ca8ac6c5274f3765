#include "control/locomotion/push_recovery.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "core/robot_model.hpp"

namespace cerebellum {

Eigen::Vector2d capture_point_world(const RobotState& state) {
  const double height_m = std::max(state.height_m, 0.05);
  return state.position_world.head<2>() + state.velocity_world.head<2>() * std::sqrt(height_m / robot::kGravityMPerS2);
}

double distance_outside_feet(const RobotState& state, const Eigen::Vector2d& point_world) {
  // feet and point in the heading frame, around the trunk
  const Eigen::Rotation2Dd to_heading(-state.rpy.z());
  const Eigen::Matrix3d body_to_world = state.orientation.toRotationMatrix();
  Eigen::Vector2d low = Eigen::Vector2d::Constant(1e9);
  Eigen::Vector2d high = Eigen::Vector2d::Constant(-1e9);
  for (const Eigen::Vector3d& foot_body : state.foot_position_body) {
    const Eigen::Vector2d foot = to_heading * (body_to_world * foot_body).head<2>();
    low = low.cwiseMin(foot);
    high = high.cwiseMax(foot);
  }
  const Eigen::Vector2d point = to_heading * (point_world - state.position_world.head<2>());
  // per axis: positive outside the interval, negative inside (distance to the nearer end)
  const Eigen::Vector2d outside = (low - point).cwiseMax(point - high);
  if ((outside.array() > 0.0).any()) return outside.cwiseMax(0.0).norm();
  return outside.maxCoeff();
}

void PushRecovery::reset() {
  stepping_ = false;
  quiet_s_ = 0.0;
  recoveries_ = 0;
}

bool PushRecovery::update(const RobotState& state, double dt_s) {
  if (!state.valid) return stepping_;
  const double tip_rate = state.omega_world.head<2>().norm();
  if (!stepping_) {
    const bool out = distance_outside_feet(state, capture_point_world(state)) > -config_.capture_margin_m;
    const double speed = state.velocity_world.head<2>().norm();
    const bool fast = speed > config_.start_speed_m_s;
    const bool shoved =
        speed > config_.shove_speed_m_s && state.accel_world.head<2>().norm() > config_.shove_accel_m_s2;
    if (out || fast || shoved || tip_rate > config_.tip_rate_rad_s) {
      stepping_ = true;
      quiet_s_ = 0.0;
      ++recoveries_;
    }
    return stepping_;
  }
  const bool quiet =
      state.velocity_world.head<2>().norm() < config_.settle_speed_m_s && tip_rate < config_.settle_tip_rate_rad_s;
  quiet_s_ = quiet ? quiet_s_ + dt_s : 0.0;
  if (quiet_s_ >= config_.settle_hold_s) stepping_ = false;
  return stepping_;
}

}  // namespace cerebellum
