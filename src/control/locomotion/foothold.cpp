#include "control/locomotion/foothold.hpp"

#include <Eigen/Geometry>
#include <algorithm>

#include "core/robot_model.hpp"

namespace cerebellum {

Eigen::Vector3d raibert_foothold(const Eigen::Vector3d& hip_world, const Eigen::Vector3d& velocity,
                                 const Eigen::Vector3d& velocity_desired,
                                 const Eigen::Vector3d& velocity_desired_before, double yaw_rate_desired, double yaw,
                                 double stance_duration_s, double body_height_m, const FootholdConfig& config,
                                 bool catching_push) {
  Eigen::Vector2d offset = Eigen::Vector2d::Zero();
  for (int axis = 0; axis < 2; ++axis) {
    // symmetric stance about the hip, corrected by the velocity error
    offset[axis] =
        0.5 * stance_duration_s * velocity[axis] + config.velocity_gain * (velocity[axis] - velocity_desired[axis]);
  }
  // centrifugal term: the foot goes outwards by half the pendulum offset (h / g) a that carries the
  // centripetal acceleration a = v x omega_des through the stance
  const double centrifugal = 0.5 * std::max(body_height_m, 0.0) / robot::kGravityMPerS2;
  offset.x() += centrifugal * (velocity.y() * yaw_rate_desired);
  offset.y() += centrifugal * (-velocity.x() * yaw_rate_desired);
  // clamp in the heading frame
  const Eigen::Rotation2Dd heading(yaw);
  Eigen::Vector2d local = heading.inverse() * offset;
  const Eigen::Vector2d error = (velocity - velocity_desired).head<2>();
  const bool pushed = error.norm() > config.push_velocity_error_m_s &&
                      (velocity - velocity_desired_before).head<2>().norm() > config.push_velocity_error_m_s;
  if (pushed && catching_push) {
    // the sideways error in the heading frame, corrected with the catch's k instead of the walking
    // k (a correction, so that every other foothold stays bit for bit what it was)
    local.y() += (config.catch_lateral_velocity_gain - config.velocity_gain) * (heading.inverse() * error).y();
  }
  const double forward = pushed ? config.max_offset_push_m : config.max_offset_forward_m;
  const double lateral = pushed ? config.max_offset_push_m : config.max_offset_lateral_m;
  local.x() = std::clamp(local.x(), -forward, forward);
  local.y() = std::clamp(local.y(), -lateral, lateral);
  offset = heading * local;
  return {hip_world.x() + offset.x(), hip_world.y() + offset.y(), hip_world.z()};
}

}  // namespace cerebellum
