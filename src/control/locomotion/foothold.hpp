// Where a swing foot lands (Raibert heuristic with velocity feedback and a centrifugal term).
#pragma once

#include <Eigen/Core>

namespace cerebellum {

struct FootholdConfig {
  double velocity_gain = 0.1;     // k in k (v - v_des)
  double max_offset_m = 0.3;      // clamp of the offset from the hip, per axis
};

// hip_world: the hip's position under the body at touchdown (world, on the ground plane);
// velocities in the world frame; stance duration in seconds; body height for the centrifugal term
Eigen::Vector3d raibert_foothold(const Eigen::Vector3d& hip_world, const Eigen::Vector3d& velocity,
                                 const Eigen::Vector3d& velocity_desired, double yaw_rate_desired,
                                 double stance_duration_s, double body_height_m, const FootholdConfig& config);

}  // namespace cerebellum
