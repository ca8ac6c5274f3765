#include "backend/push_request.hpp"

#include <cmath>

namespace cerebellum {

std::array<double, 3> push_force(const PushRequest& request, const std::array<double, 3>& com_world,
                                 const std::array<double, 3>& com_velocity_world, const PushSpring& spring) {
  std::array<double, 3> force{};
  if (!request.active) return force;
  double norm_sq = 0.0;
  for (int k = 0; k < 3; ++k) {
    force[k] = spring.stiffness_n_per_m * (request.target_world[k] - com_world[k]) -
               spring.damping_n_s_per_m * com_velocity_world[k];
    norm_sq += force[k] * force[k];
  }
  const double norm = std::sqrt(norm_sq);
  if (norm > spring.max_force_n) {
    for (double& f : force) f *= spring.max_force_n / norm;
  }
  return force;
}

}  // namespace cerebellum
