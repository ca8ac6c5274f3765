#include "control/orientation_trim.hpp"

#include "control/stance_frame.hpp"

namespace cerebellum {

Eigen::Vector3d OrientationTrim::update(const Eigen::Vector3d& target_rpy, const Eigen::Vector3d& measured_rpy,
                                        double dt_s) {
  Eigen::Vector3d error = target_rpy - measured_rpy;
  error.z() = wrap_angle(error.z());
  trim_ = (trim_ + dt_s * config_.gain_per_s * error).cwiseMax(-config_.max_trim_rad).cwiseMin(config_.max_trim_rad);
  return target_rpy + trim_;
}

}  // namespace cerebellum
