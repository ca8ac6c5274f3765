// Slow outer loop for poses set through leg kinematics: the IMU's orientation is compared with
// the target and the difference is integrated into the orientation the legs are asked for, so
// that feet rolling on their spheres, slipping or joint compliance do not leave the body off.
#pragma once

#include <Eigen/Core>

namespace cerebellum {

struct OrientationTrimConfig {
  double gain_per_s = 3.0;    // integral gain on the orientation error
  double max_trim_rad = 0.1;  // per axis
};

class OrientationTrim {
 public:
  explicit OrientationTrim(const OrientationTrimConfig& config = {}) : config_(config) {}
  void reset() { trim_.setZero(); }
  // target and measured roll, pitch, yaw (same frame); returns the orientation to command
  Eigen::Vector3d update(const Eigen::Vector3d& target_rpy, const Eigen::Vector3d& measured_rpy, double dt_s);

 private:
  OrientationTrimConfig config_;
  Eigen::Vector3d trim_ = Eigen::Vector3d::Zero();
};

}  // namespace cerebellum
