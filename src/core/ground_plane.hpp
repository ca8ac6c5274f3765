// The ground under the robot as a plane z = z_c + g . ((x, y) - c): the estimator's belief,
// carried in RobotState, which footholds, height and attitude references are taken from.
#pragma once

#include <Eigen/Core>
#include <cmath>

namespace cerebellum {

struct GroundPlane {
  Eigen::Vector2d centre_xy = Eigen::Vector2d::Zero();  // world x, y the plane passes through
  double centre_z = 0.0;                                // its height there (m)
  Eigen::Vector2d gradient = Eigen::Vector2d::Zero();   // dz/dx, dz/dy

  double height_at(double x, double y) const { return centre_z + gradient.dot(Eigen::Vector2d(x, y) - centre_xy); }
  // ground pitch and roll seen along a heading (rad): nose-up on an uphill is negative pitch
  double pitch_along(double yaw) const {
    return -std::atan(gradient.dot(Eigen::Vector2d(std::cos(yaw), std::sin(yaw))));
  }
  double roll_along(double yaw) const {
    return std::atan(gradient.dot(Eigen::Vector2d(-std::sin(yaw), std::cos(yaw))));
  }
};

}  // namespace cerebellum
