// A push on the trunk, a disturbance input of the simulation (the viewer's ctrl + drag): while
// active, a spring pulls the trunk's centre of mass towards target_world. The simulation turns it
// into a force at each of its physics steps.
#pragma once

#include <array>

namespace cerebellum {

struct PushRequest {
  bool active = false;
  std::array<double, 3> target_world{};
};

struct PushSpring {
  // at most about 0.5 g on the 8.5 kg robot: a push it can stand against, not a throw
  double stiffness_n_per_m = 150.0;
  double damping_n_s_per_m = 15.0;
  double max_force_n = 40.0;
};

// A constant force on the trunk's centre of mass (world frame) for a span of simulated time: the
// `cerebellum push` verb's disturbance, for people and tests. A new pulse replaces a running one.
struct ForcePulse {
  std::array<double, 3> force_n{};
  double duration_s = 0.0;
};

// world-frame force on the trunk: stiffness * (target - com) - damping * com_velocity, its
// magnitude limited to max_force_n; zero when the request is not active
std::array<double, 3> push_force(const PushRequest& request, const std::array<double, 3>& com_world,
                                 const std::array<double, 3>& com_velocity_world, const PushSpring& spring);

}  // namespace cerebellum
