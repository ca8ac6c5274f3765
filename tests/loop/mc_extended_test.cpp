// The MC beyond the product (config/extended.yaml, as shipped): the flying trot runs at 2.5 m/s,
// while the default configuration keeps the product's 1.6 m/s clamp. Lockstep, judged on the
// simulator's truth.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "control/locomotion/gait_table.hpp"
#include "loop/simulated_robot.hpp"
#include "mc_fixture.hpp"

namespace cerebellum {
namespace {

using testing::command;
using testing::lying_start;

McConfig extended() {
  McConfig config = load_config(std::string(CEREBELLUM_SOURCE_DIR) + "/config/extended.yaml");
  config.startup = Startup::Off;
  return config;
}

// the trunk's mean forward speed on the truth over the last measure_s of a walk at vx
double true_forward_speed(McConfig config, double vx, double settle_s, double measure_s) {
  Mc mc = make_simulated_mc(config);
  LockstepClient client(mc);
  client.run(command(ModeId::RecoveryStand, 0), 3.0);
  client.run(command(ModeId::Locomotion, kFlyingTrotGaitId, vx), settle_s);
  const double x0 = mc.simulation().ground_truth().position[0];
  client.run(command(ModeId::Locomotion, kFlyingTrotGaitId, vx), measure_s);
  EXPECT_GT(mc.simulation().ground_truth().position[2], 0.18) << "the trunk stays up";
  EXPECT_EQ(mc.machine().status().mode, 11);
  return (mc.simulation().ground_truth().position[0] - x0) / measure_s;
}

TEST(McExtended, TheExtendedConfigurationTrotsAt2Point5MetresPerSecondWithinFivePercent) {
  const double speed = true_forward_speed(extended(), 2.5, 2.5, 2.0);
  EXPECT_NEAR(speed, 2.5, 0.05 * 2.5);
}

TEST(McExtended, TheDefaultConfigurationClampsTheSameCommandToTheProducts1Point6) {
  const double product_max = find_gait(kFlyingTrotGaitId)->velocity_max[0];
  const double speed = true_forward_speed(lying_start(), 2.5, 2.5, 2.0);
  EXPECT_NEAR(speed, product_max, 0.1 * product_max);
}

}  // namespace
}  // namespace cerebellum
