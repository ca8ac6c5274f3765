#include "control/locomotion/swing_trajectory.hpp"

#include <algorithm>

namespace cerebellum {

double cubic_bezier(double from, double to, double s) {
  // control points from, from, to, to: from + (to - from) (3 s^2 - 2 s^3)
  return from + (to - from) * s * s * (3.0 - 2.0 * s);
}

double cubic_bezier_derivative(double from, double to, double s) { return (to - from) * 6.0 * s * (1.0 - s); }

SwingPoint swing_point(const Eigen::Vector3d& start, const Eigen::Vector3d& end, double height_m, double phase,
                       double duration_s) {
  const double s = std::clamp(phase, 0.0, 1.0);
  SwingPoint point;
  for (int axis = 0; axis < 2; ++axis) {
    point.position[axis] = cubic_bezier(start[axis], end[axis], s);
    point.velocity[axis] = cubic_bezier_derivative(start[axis], end[axis], s) / duration_s;
  }
  const double apex = std::max(start.z(), end.z()) + height_m;
  if (s < 0.5) {
    point.position.z() = cubic_bezier(start.z(), apex, 2.0 * s);
    point.velocity.z() = 2.0 * cubic_bezier_derivative(start.z(), apex, 2.0 * s) / duration_s;
  } else {
    point.position.z() = cubic_bezier(apex, end.z(), 2.0 * s - 1.0);
    point.velocity.z() = 2.0 * cubic_bezier_derivative(apex, end.z(), 2.0 * s - 1.0) / duration_s;
  }
  return point;
}

}  // namespace cerebellum
