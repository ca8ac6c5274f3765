#include "estimation/ground_plane_tracker.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>

namespace cerebellum {

bool fit_ground_plane(const std::array<Eigen::Vector3d, kNumLegs>& points, GroundPlane& plane) {
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const auto& p : points) mean += p;
  mean /= static_cast<double>(points.size());
  // normal equations of z - z_mean = g . (xy - xy_mean)
  Eigen::Matrix2d sxx = Eigen::Matrix2d::Zero();
  Eigen::Vector2d sxz = Eigen::Vector2d::Zero();
  for (const auto& p : points) {
    const Eigen::Vector3d d = p - mean;
    sxx += d.head<2>() * d.head<2>().transpose();
    sxz += d.head<2>() * d.z();
  }
  const double scale = sxx.trace();
  if (!(scale > 1e-8) || sxx.determinant() < 1e-6 * scale * scale) return false;
  const Eigen::Vector2d gradient = sxx.inverse() * sxz;
  if (!gradient.allFinite()) return false;
  plane.centre_xy = mean.head<2>();
  plane.centre_z = mean.z();
  plane.gradient = gradient;
  return true;
}

void GroundPlaneTracker::reset(const std::array<Eigen::Vector3d, kNumLegs>& feet_world) {
  planted_slope_ = planted_height_ = feet_world;
  raw_gradient_.setZero();
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const auto& p : feet_world) mean += p;
  mean /= static_cast<double>(kNumLegs);
  plane_ = GroundPlane{mean.head<2>(), mean.z(), Eigen::Vector2d::Zero()};
}

void GroundPlaneTracker::update(const std::array<Eigen::Vector3d, kNumLegs>& slope_points,
                                const std::array<Eigen::Vector3d, kNumLegs>& height_points,
                                const std::array<bool, kNumLegs>& planted, double dt_s) {
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
    if (planted[leg] && slope_points[leg].allFinite() && height_points[leg].allFinite()) {
      planted_slope_[leg] = slope_points[leg];
      planted_height_[leg] = height_points[leg];
    }
  }
  GroundPlane fit;
  if (fit_ground_plane(planted_slope_, fit)) {
    const double alpha = std::clamp(dt_s / std::max(config_.gradient_time_constant_s, 1e-6), 0.0, 1.0);
    raw_gradient_ += alpha * (fit.gradient - raw_gradient_);
    // through the centroid of the height points
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    for (const auto& p : planted_height_) mean += p;
    mean /= static_cast<double>(kNumLegs);
    plane_.centre_xy = mean.head<2>();
    plane_.centre_z = mean.z();
  }
  // deadband then clamp on the slope's tangent
  const double flat = std::tan(config_.flat_slope_rad);
  const double steepest = std::tan(config_.max_slope_rad);
  const double slope = raw_gradient_.norm();
  const double kept = std::clamp(slope - flat, 0.0, steepest);
  plane_.gradient = slope > 0.0 ? Eigen::Vector2d(raw_gradient_ * (kept / slope)) : Eigen::Vector2d::Zero();
}

}  // namespace cerebellum
