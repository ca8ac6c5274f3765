// Fits and tracks the ground plane (core/ground_plane.hpp) through the points where the feet
// were last planted. Robust for control: only feet planted for a while count, the gradient is
// low-passed, small slopes read as flat and steep ones are clamped.
#pragma once

#include <Eigen/Core>
#include <array>

#include "core/ground_plane.hpp"
#include "core/joint_layout.hpp"

namespace cerebellum {

// least-squares plane through the points (vertical residuals); false (plane unchanged) when
// their x, y are (nearly) collinear
bool fit_ground_plane(const std::array<Eigen::Vector3d, kNumLegs>& points, GroundPlane& plane);

struct GroundPlaneTrackerConfig {
  double gradient_time_constant_s = 0.3;  // low-pass of the fitted gradient
  double flat_slope_rad = 0.035;          // slopes up to this read as flat (about 2 degrees)
  double max_slope_rad = 0.35;            // steeper fits are clamped to this (about 20 degrees)
};

class GroundPlaneTracker {
 public:
  explicit GroundPlaneTracker(const GroundPlaneTrackerConfig& config = {}) : config_(config) {}

  // every foot planted where it is now, the ground flat through them
  void reset(const std::array<Eigen::Vector3d, kNumLegs>& feet_world);
  // feet_world: foot contact points (world); planted: legs in stance for a while, whose points
  // replace the stored ones
  void update(const std::array<Eigen::Vector3d, kNumLegs>& feet_world, const std::array<bool, kNumLegs>& planted,
              double dt_s) {
    update(feet_world, feet_world, planted, dt_s);
  }
  // the same with two estimates of the contact points: the slope from one (their differences),
  // the height the plane passes through from the other
  void update(const std::array<Eigen::Vector3d, kNumLegs>& slope_points,
              const std::array<Eigen::Vector3d, kNumLegs>& height_points, const std::array<bool, kNumLegs>& planted,
              double dt_s);
  const GroundPlane& plane() const { return plane_; }

 private:
  GroundPlaneTrackerConfig config_;
  std::array<Eigen::Vector3d, kNumLegs> planted_slope_{};
  std::array<Eigen::Vector3d, kNumLegs> planted_height_{};
  Eigen::Vector2d raw_gradient_ = Eigen::Vector2d::Zero();  // low-passed fit, before deadband
  GroundPlane plane_;
};

}  // namespace cerebellum
