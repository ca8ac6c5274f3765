// Roll, pitch, yaw of an orientation, one convention for the estimator, telemetry and tools.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace cerebellum {

// ZYX Euler angles (rad) of q, the inverse of yaw about z, then pitch about y, then roll about x:
// q = Rz(yaw) Ry(pitch) Rx(roll). q is used as given (not normalised). Pitch is kept in
// [-pi/2, pi/2]: at gimbal lock rounding cannot push its sine past +-1 into NaN.
Eigen::Vector3d rpy_from_quaternion(const Eigen::Quaterniond& q);

}  // namespace cerebellum
