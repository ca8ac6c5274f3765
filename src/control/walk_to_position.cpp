#include "control/walk_to_position.hpp"

#include <algorithm>
#include <cmath>

#include "control/stance_frame.hpp"

namespace cerebellum {

WalkToPositionOutput WalkToPosition::update(const Pose2d& trunk, const Pose2d& target, double max_speed_m_s) {
  const Eigen::Vector2d error_world = target.position - trunk.position;
  const double yaw_error = wrap_angle(target.yaw_rad - trunk.yaw_rad);
  const double distance = error_world.norm();

  // hysteresis: stand once close, walk again only once clearly away
  if (arrived_) {
    arrived_ = distance < config_.leave_position_m && std::abs(yaw_error) < config_.leave_yaw_rad;
  } else {
    arrived_ = distance < config_.arrive_position_m && std::abs(yaw_error) < config_.arrive_yaw_rad;
  }
  WalkToPositionOutput out;
  out.arrived = arrived_;
  if (arrived_) return out;

  // the error in the body frame: walk straight at the target, whatever the heading
  const double c = std::cos(trunk.yaw_rad), s = std::sin(trunk.yaw_rad);
  Eigen::Vector2d velocity(c * error_world.x() + s * error_world.y(), -s * error_world.x() + c * error_world.y());
  velocity *= config_.position_gain_per_s;
  // the lateral limit first, then the speed limit, both keeping the direction
  const double lateral_limit = config_.max_lateral_share * max_speed_m_s;
  if (std::abs(velocity.y()) > lateral_limit) velocity *= lateral_limit / std::abs(velocity.y());
  if (velocity.norm() > max_speed_m_s) velocity *= max_speed_m_s / velocity.norm();
  out.velocity.head<2>() = velocity;
  out.velocity.z() =
      std::clamp(config_.yaw_gain_per_s * yaw_error, -config_.max_yaw_rate_rad_s, config_.max_yaw_rate_rad_s);
  return out;
}

}  // namespace cerebellum
