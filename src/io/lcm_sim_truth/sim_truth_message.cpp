#include "io/lcm_sim_truth/sim_truth_message.hpp"

#include <cmath>

namespace cerebellum {

sim_truth_lcmt make_sim_truth_message(const GroundTruth& truth, double time_s) {
  sim_truth_lcmt message{};
  message.timestamp = static_cast<int64_t>(std::llround(time_s * 1e9));
  for (int k = 0; k < 3; ++k) {
    message.position[k] = truth.position[k];
    message.velocity[k] = truth.velocity_world[k];
    message.angular_velocity[k] = truth.angular_velocity_body[k];
  }
  for (int k = 0; k < 4; ++k) message.quaternion[k] = truth.quat[k];
  message.ground_height = truth.ground_height_m;
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) message.foot_contact[leg] = truth.foot_contact[leg];
  for (std::size_t i = 0; i < kNumJoints; ++i) {
    message.q[i] = truth.q[i];
    message.qd[i] = truth.qd[i];
    message.tau[i] = truth.tau[i];
  }
  return message;
}

}  // namespace cerebellum
