// What an accelerometer measures: the specific force f = a - g (m/s^2), the push of everything
// but gravity per unit mass. At rest it reads gravity's reaction, +9.81 up; in free fall, zero.
// The IMU fields of every interface carry f as the robot's IMU does; the estimator and the
// controllers work with the acceleration a = f + g. Gravity's figure has its one home in
// robot_model.hpp (robot::kGravityMPerS2).
#pragma once

#include <Eigen/Core>

#include "core/robot_model.hpp"

namespace cerebellum {

// gravity's acceleration in the world frame (z up)
inline Eigen::Vector3d gravity_world() { return {0.0, 0.0, -robot::kGravityMPerS2}; }

// what an accelerometer at rest reads, world frame: gravity's reaction, straight up
inline Eigen::Vector3d specific_force_at_rest_world() { return -gravity_world(); }

// the acceleration (world) of a point whose accelerometer reads specific_force_world (turned
// into the world frame): a = f + g
inline Eigen::Vector3d acceleration_from_specific_force(const Eigen::Vector3d& specific_force_world) {
  return specific_force_world + gravity_world();
}

}  // namespace cerebellum
