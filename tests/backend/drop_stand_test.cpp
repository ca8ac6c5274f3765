// End to end in lockstep simulated time: dropped from 0.3 m, the stand-up controller brings the
// robot to rest standing.
#include <gtest/gtest.h>

#include <cmath>

#include "backend/sim_fixture.hpp"
#include "control/stand_up_controller.hpp"
#include "core/robot_model.hpp"

namespace cerebellum {
namespace {

TEST(DropAndStand, ComesToRestStandingWithinThreeSeconds) {
  StandUpController stand_up(default_stand_up_config());
  testing::LockstepSim sim(testing::sim_config(0.3), stand_up);
  bool all_finite = true;
  double worst_limit_violation = 0.0;
  while (sim.backend.time_s() < 3.0 - 1e-9) {
    const CycleRecord& record = sim.loop.tick();
    for (std::size_t i = 0; i < kNumJoints; ++i) {
      const double q = record.state.q[i];
      all_finite &= std::isfinite(q) && std::isfinite(record.state.qd[i]);
      const robot::JointRange range = robot::joint_range(i);
      worst_limit_violation = std::max({worst_limit_violation, range.lower - q, q - range.upper});
    }
  }
  const GroundTruth truth = sim.backend.ground_truth();
  EXPECT_TRUE(all_finite);
  EXPECT_GE(truth.position[2], 0.20);
  EXPECT_LE(truth.position[2], 0.27);
  // at rest and level
  for (double v : truth.velocity_world) EXPECT_LT(std::abs(v), 0.02);
  EXPECT_GT(truth.quat[0], std::cos(0.05 / 2));
  // MuJoCo's limits are soft constraints: allow a millimetre-scale penetration only
  EXPECT_LT(worst_limit_violation, 0.005);
  EXPECT_NEAR(stand_up.progress(), 1.0, 1e-12);
}

TEST(DropAndStand, EstimatedHeightAgreesWithTheSimulatorOnceStanding) {
  StandUpController stand_up(default_stand_up_config());
  testing::LockstepSim sim(testing::sim_config(0.3), stand_up);
  sim.run_for(3.0);
  const RobotState& state = sim.loop.last_cycle().state;
  EXPECT_NEAR(state.height_m, sim.backend.ground_truth().position[2], 0.01);
  for (double c : state.contact) EXPECT_EQ(c, 1.0);
}

TEST(DropAndStand, WithoutCommandsTheRobotCollapses) {
  // the control test above can fail: with passive motors the same drop ends low
  class Limp final : public MotionController {
    void compute(const RobotState&, JointCommand& command) override { command = JointCommand{}; }
  } limp;
  testing::LockstepSim sim(testing::sim_config(0.3), limp);
  sim.run_for(3.0);
  EXPECT_LT(sim.backend.ground_truth().position[2], 0.15);
}

}  // namespace
}  // namespace cerebellum
