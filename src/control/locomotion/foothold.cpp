#include "control/locomotion/foothold.hpp"

#include <algorithm>

namespace cerebellum {

Eigen::Vector3d raibert_foothold(const Eigen::Vector3d& hip_world, const Eigen::Vector3d& velocity,
                                 const Eigen::Vector3d& velocity_desired, double yaw_rate_desired,
                                 double stance_duration_s, double body_height_m, const FootholdConfig& config) {
  Eigen::Vector3d offset = Eigen::Vector3d::Zero();
  for (int axis = 0; axis < 2; ++axis) {
    // symmetric stance about the hip, corrected by the velocity error
    offset[axis] = 0.5 * stance_duration_s * velocity[axis] +
                   config.velocity_gain * (velocity[axis] - velocity_desired[axis]);
  }
  // centrifugal term: 0.5 sqrt(h / g) (v x omega_des)
  const double centrifugal = 0.5 * std::sqrt(std::max(body_height_m, 0.0) / 9.81);
  offset.x() += centrifugal * (velocity.y() * yaw_rate_desired);
  offset.y() += centrifugal * (-velocity.x() * yaw_rate_desired);
  for (int axis = 0; axis < 2; ++axis) offset[axis] = std::clamp(offset[axis], -config.max_offset_m, config.max_offset_m);
  Eigen::Vector3d foothold = hip_world + offset;
  foothold.z() = hip_world.z();
  return foothold;
}

}  // namespace cerebellum
