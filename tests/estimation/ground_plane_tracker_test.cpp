// The ground plane fit against a full least-squares solve of z = a + b x + c y, and the
// tracker's planted-feet rule, low-pass, deadband and clamp, slope and height from two point sets.
#include "estimation/ground_plane_tracker.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <random>

namespace cerebellum {
namespace {

using Feet = std::array<Eigen::Vector3d, kNumLegs>;

Feet feet_on(double a, double b, double c, double cx, double cy) {
  Feet feet;
  const double xs[] = {0.24, 0.24, -0.24, -0.24};
  const double ys[] = {-0.12, 0.12, -0.12, 0.12};
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
    const double x = cx + xs[leg], y = cy + ys[leg];
    feet[leg] = Eigen::Vector3d(x, y, a + b * x + c * y);
  }
  return feet;
}

TEST(GroundPlaneFit, MatchesFullLeastSquaresOnNoisyPoints) {
  std::mt19937 rng(3);
  std::normal_distribution<double> noise(0.0, 0.01);
  std::uniform_real_distribution<double> spread(-0.3, 0.3);
  for (int trial = 0; trial < 50; ++trial) {
    Feet points;
    Eigen::Matrix<double, kNumLegs, 3> a;
    Eigen::Matrix<double, kNumLegs, 1> z;
    for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
      points[leg] = Eigen::Vector3d(2.0 + spread(rng), -1.0 + spread(rng), 0.4 + 0.2 * spread(rng) + noise(rng));
      a.row(leg) << 1.0, points[leg].x(), points[leg].y();
      z(leg) = points[leg].z();
    }
    const Eigen::Vector3d abc = a.colPivHouseholderQr().solve(z);
    GroundPlane plane;
    ASSERT_TRUE(fit_ground_plane(points, plane));
    EXPECT_NEAR(plane.gradient.x(), abc(1), 1e-9);
    EXPECT_NEAR(plane.gradient.y(), abc(2), 1e-9);
    for (const auto& p : points)
      EXPECT_NEAR(plane.height_at(p.x(), p.y()), abc(0) + abc(1) * p.x() + abc(2) * p.y(), 1e-9);
  }
}

TEST(GroundPlaneFit, RefusesCollinearPoints) {
  Feet points;
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) points[leg] = Eigen::Vector3d(0.1 * leg, 0.2 * leg, 0.05 * leg);
  GroundPlane plane;
  plane.centre_z = 7.0;
  EXPECT_FALSE(fit_ground_plane(points, plane));
  EXPECT_EQ(plane.centre_z, 7.0);
}

TEST(GroundPlaneTracker, ConvergesToA10DegreeRampAndGivesItsPitch) {
  const double slope = std::tan(10.0 * M_PI / 180.0);
  GroundPlaneTracker tracker;
  tracker.reset(feet_on(0.0, 0.0, 0.0, 0.0, 0.0));
  const Feet ramp = feet_on(-0.1, slope, 0.0, 1.5, 0.0);
  const std::array<bool, kNumLegs> all{true, true, true, true};
  for (int i = 0; i < 2000; ++i) tracker.update(ramp, all, 0.002);  // 4 s, > 10 time constants
  const GroundPlane& plane = tracker.plane();
  // the deadband takes its slope off the fitted one
  const double expected = slope - std::tan(GroundPlaneTrackerConfig{}.flat_slope_rad);
  EXPECT_NEAR(plane.gradient.x(), expected, 1e-6);
  EXPECT_NEAR(plane.gradient.y(), 0.0, 1e-9);
  EXPECT_NEAR(plane.height_at(1.5, 0.0), -0.1 + slope * 1.5, 1e-9);  // through the feet's centroid
  const double angle = std::atan(plane.gradient.x());
  EXPECT_NEAR(tracker.plane().pitch_along(0.0), -angle, 1e-12);  // uphill ahead: nose up
  EXPECT_NEAR(tracker.plane().pitch_along(M_PI), angle, 1e-12);
  EXPECT_NEAR(tracker.plane().roll_along(M_PI / 2), -angle, 1e-12);  // ground rises to the right
  EXPECT_NEAR(tracker.plane().roll_along(0.0), 0.0, 1e-12);
}

TEST(GroundPlaneTracker, SmallSlopesReadFlatAndSteepOnesAreClamped) {
  const std::array<bool, kNumLegs> all{true, true, true, true};
  GroundPlaneTracker tracker;
  tracker.reset(feet_on(0.0, 0.0, 0.0, 0.0, 0.0));
  for (int i = 0; i < 2000; ++i) tracker.update(feet_on(0.0, 0.02, -0.01, 0.0, 0.0), all, 0.002);
  EXPECT_EQ(tracker.plane().gradient.norm(), 0.0);
  for (int i = 0; i < 4000; ++i) tracker.update(feet_on(0.0, 1.0, 0.0, 0.0, 0.0), all, 0.002);  // 45 degrees
  EXPECT_NEAR(tracker.plane().gradient.norm(), std::tan(GroundPlaneTrackerConfig{}.max_slope_rad), 1e-9);
}

TEST(GroundPlaneTracker, OnlyPlantedFeetMoveThePlaneAndTheGradientIsLowPassed) {
  GroundPlaneTracker tracker;
  tracker.reset(feet_on(0.0, 0.0, 0.0, 0.0, 0.0));
  Feet lifted = feet_on(0.0, 0.0, 0.0, 0.0, 0.0);
  lifted[0].z() = 0.5;  // a swinging foot high in the air
  tracker.update(lifted, {false, true, true, true}, 0.002);
  EXPECT_EQ(tracker.plane().centre_z, 0.0);
  EXPECT_EQ(tracker.plane().gradient.norm(), 0.0);
  // one step of a planted step change: the gradient moves by dt / tau of the way
  const double slope = 0.5;
  tracker.update(feet_on(0.0, slope, 0.0, 0.0, 0.0), {true, true, true, true}, 0.03);
  const double raw = slope * 0.03 / GroundPlaneTrackerConfig{}.gradient_time_constant_s;
  EXPECT_NEAR(tracker.plane().gradient.x(), raw - std::tan(GroundPlaneTrackerConfig{}.flat_slope_rad), 1e-9);
}

TEST(GroundPlaneTracker, SlopeComesFromOnePointSetAndHeightFromTheOther) {
  const double slope = std::tan(10.0 * M_PI / 180.0);
  GroundPlaneTracker tracker;
  tracker.reset(feet_on(0.0, 0.0, 0.0, 0.0, 0.0));
  // measured feet on a ramp through z = 0.2 at their centroid; the height estimate flat at 0.05
  const Feet on_ramp = feet_on(0.2 - slope * 1.0, slope, 0.0, 1.0, 0.0);
  const Feet level = feet_on(0.05, 0.0, 0.0, 1.0, 0.0);
  const std::array<bool, kNumLegs> all{true, true, true, true};
  for (int i = 0; i < 2000; ++i) tracker.update(on_ramp, level, all, 0.002);
  const double expected = slope - std::tan(GroundPlaneTrackerConfig{}.flat_slope_rad);
  EXPECT_NEAR(tracker.plane().gradient.x(), expected, 1e-6);
  EXPECT_NEAR(tracker.plane().height_at(1.0, 0.0), 0.05, 1e-12);
  EXPECT_NEAR(tracker.plane().height_at(2.0, 0.0), 0.05 + expected, 1e-6);
}

}  // namespace
}  // namespace cerebellum
