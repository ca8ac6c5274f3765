// A swing foot's path: cubic Bezier in x-y from lift-off to touchdown; in z up to the swing
// height during the first half and back down during the second, each half a cubic Bezier
// (zero vertical speed at lift-off, apex and touchdown).
#pragma once

#include <Eigen/Core>

namespace cerebellum {

struct SwingPoint {
  Eigen::Vector3d position;
  Eigen::Vector3d velocity;  // per second
};

// phase 0..1, duration in seconds; start and end are foot positions (world), height above them
SwingPoint swing_point(const Eigen::Vector3d& start, const Eigen::Vector3d& end, double height_m, double phase,
                       double duration_s);

// cubic Bezier with control points at the ends (zero end slopes): value and d/ds
double cubic_bezier(double from, double to, double s);
double cubic_bezier_derivative(double from, double to, double s);

}  // namespace cerebellum
