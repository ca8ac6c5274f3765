// The ground plane value type: heights on the plane, and its pitch and roll along a heading
// checked against rises measured with height_at.
#include "core/ground_plane.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace cerebellum {
namespace {

GroundPlane tilted_plane() {
  GroundPlane plane;
  plane.centre_xy = Eigen::Vector2d(1.0, -0.5);
  plane.centre_z = 0.2;
  plane.gradient = Eigen::Vector2d(0.15, -0.08);
  return plane;
}

TEST(GroundPlane, PassesThroughItsCentreAlongItsGradient) {
  const GroundPlane plane = tilted_plane();
  EXPECT_DOUBLE_EQ(plane.height_at(1.0, -0.5), 0.2);
  EXPECT_NEAR(plane.height_at(2.0, -0.5), 0.2 + 0.15, 1e-12);
  EXPECT_NEAR(plane.height_at(1.0, 0.5), 0.2 - 0.08, 1e-12);
}

TEST(GroundPlane, PitchAndRollMatchTheRiseMeasuredAheadAndToTheLeft) {
  const GroundPlane plane = tilted_plane();
  const double step_m = 0.3;
  for (double yaw : {0.0, 0.7, 2.0, -2.5}) {
    const Eigen::Vector2d ahead(std::cos(yaw), std::sin(yaw));
    const Eigen::Vector2d left(-std::sin(yaw), std::cos(yaw));
    const Eigen::Vector2d p(0.4, 0.9);
    const double h = plane.height_at(p.x(), p.y());
    const Eigen::Vector2d a = p + step_m * ahead;
    const Eigen::Vector2d l = p + step_m * left;
    // ground rising ahead tilts the nose up (negative pitch); rising to the left rolls right side down
    EXPECT_NEAR(plane.pitch_along(yaw), -std::atan2(plane.height_at(a.x(), a.y()) - h, step_m), 1e-12);
    EXPECT_NEAR(plane.roll_along(yaw), std::atan2(plane.height_at(l.x(), l.y()) - h, step_m), 1e-12);
  }
}

}  // namespace
}  // namespace cerebellum
