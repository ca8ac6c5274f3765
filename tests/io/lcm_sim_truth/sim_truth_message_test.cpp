// sim_truth_lcmt carries each field of the ground truth unchanged, time in ns.
#include <gtest/gtest.h>

#include "io/lcm_sim_truth/sim_truth_message.hpp"

namespace cerebellum {
namespace {

TEST(SimTruthMessage, CarriesEveryFieldOfTheGroundTruthUnchanged) {
  GroundTruth truth;
  truth.position = {1.5, -2.25, 0.26};
  truth.quat = {0.5, 0.5, -0.5, 0.5};
  truth.velocity_world = {0.3, -0.1, 0.02};
  truth.angular_velocity_body = {0.01, -0.02, 0.7};
  truth.foot_contact = {true, false, false, true};
  for (std::size_t i = 0; i < kNumJoints; ++i) {
    truth.q[i] = 0.1 * static_cast<double>(i) - 0.5;
    truth.qd[i] = -0.3 * static_cast<double>(i);
    truth.tau[i] = 0.7 * static_cast<double>(i) - 4.0;
  }
  const sim_truth_lcmt message = make_sim_truth_message(truth, 12.345678901);
  EXPECT_EQ(message.timestamp, 12345678901);
  for (int k = 0; k < 3; ++k) {
    EXPECT_EQ(message.position[k], truth.position[k]);
    EXPECT_EQ(message.velocity[k], truth.velocity_world[k]);
    EXPECT_EQ(message.angular_velocity[k], truth.angular_velocity_body[k]);
  }
  for (int k = 0; k < 4; ++k) EXPECT_EQ(message.quaternion[k], truth.quat[k]);
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) EXPECT_EQ(message.foot_contact[leg] != 0, truth.foot_contact[leg]);
  for (std::size_t i = 0; i < kNumJoints; ++i) {
    EXPECT_EQ(message.q[i], truth.q[i]);
    EXPECT_EQ(message.qd[i], truth.qd[i]);
    EXPECT_EQ(message.tau[i], truth.tau[i]);
  }
}

}  // namespace
}  // namespace cerebellum
