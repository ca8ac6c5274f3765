// The whole MC in lockstep on a robot that is not the model it was tuned for (issue 43's soak
// under model error): the two corners of the soak's ranges, each part at its end, stand and trot.
// Judged on the simulator's truth; the MC controls on its own estimate and is told nothing.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "core/robot_model.hpp"
#include "loop/simulated_robot.hpp"
#include "mc_fixture.hpp"

namespace cerebellum {
namespace {

using testing::command;
using testing::lying_start;

struct TrotResult {
  double largest_tilt_rad = 0.0;
  double lowest_height_m = 1.0;
  double speed_m_s = 0.0;
};

// stand 3 s, then trot (gait 3) at 1 m/s for 6 s; the speed over its last 3 s
TrotResult stand_and_trot(const ModelError& error) {
  McConfig config = lying_start(true, 43);
  config.robot.model_error = error;
  config.robot.noise.scale(2.0);  // the soak's sensor noise x2
  Mc mc = make_simulated_mc(config);
  LockstepClient client(mc);
  TrotResult result;
  const auto watch = [&](const CycleRecord&) {
    result.largest_tilt_rad = std::max(result.largest_tilt_rad, testing::truth_tilt_rad(mc.simulation().ground_truth()));
  };
  client.run(command(ModeId::RecoveryStand, 0), 3.0);
  client.run(command(ModeId::Locomotion, 3, 1.0), 3.0, watch);
  const double x0 = mc.simulation().ground_truth().position[0];
  client.run(command(ModeId::Locomotion, 3, 1.0), 3.0, [&](const CycleRecord& record) {
    watch(record);
    result.lowest_height_m = std::min(result.lowest_height_m, mc.simulation().ground_truth().position[2]);
  });
  result.speed_m_s = (mc.simulation().ground_truth().position[0] - x0) / 3.0;
  return result;
}

TEST(McModelError, AHeavySlipperyRobotWithWeakLateMotorsAndItsMassForwardStandsAndTrotsAtTheCommandedSpeed) {
  ModelError error;
  error.added_mass_kg = 0.15 * robot::kTotalMassKg;
  error.com_offset_m = {0.02, 0.02, 0.02};
  error.foot_friction = 0.4;
  error.motor_strength_scale = 0.85;
  error.actuation_delay_s = 0.004;
  const TrotResult r = stand_and_trot(error);
  EXPECT_LT(r.largest_tilt_rad, 0.6);
  EXPECT_GT(r.lowest_height_m, 0.2);
  EXPECT_NEAR(r.speed_m_s, 1.0, 0.15);
}

TEST(McModelError, ALightGrippyRobotWithStrongMotorsAndItsMassBackStandsAndTrotsAtTheCommandedSpeed) {
  ModelError error;
  error.added_mass_kg = -0.15 * robot::kTotalMassKg;
  error.com_offset_m = {-0.02, -0.02, -0.02};
  error.foot_friction = 1.2;
  error.motor_strength_scale = 1.15;
  const TrotResult r = stand_and_trot(error);
  EXPECT_LT(r.largest_tilt_rad, 0.6);
  EXPECT_GT(r.lowest_height_m, 0.2);
  EXPECT_NEAR(r.speed_m_s, 1.0, 0.15);
}

}  // namespace
}  // namespace cerebellum
