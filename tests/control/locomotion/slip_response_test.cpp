// The slip response (LocomotionConfig::slip_response) end to end in lockstep simulation: on a
// floor of friction 0.3 (every foot's, in the simulator) the blind MC learns from its stance feet
// that the ground is slippery and then widens a fast turn and ramps its command gently; on the
// model's floor it does neither. (A steady walk on 0.43 hardly slips: there the soak's slips come
// from changes of command, which a short test does not reproduce.)
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "control/qp/goldfarb_idnani_solver.hpp"
#include "walking_fixture.hpp"

namespace cerebellum {
namespace {

using testing::StandThenWalk;
using testing::walk_command;
using testing::WalkingSim;

constexpr double kStart = StandThenWalk::kStandSeconds;
constexpr double kSlipperyFloorFriction = 0.3;

LocomotionConfig responding() {
  LocomotionConfig config;
  config.slip_response = true;
  return config;
}

// a flying trot at 1.2 m/s turning at 1.2 rad/s: 1.44 m/s^2 centripetal, within the product's
// 1.5 but not within the slippery ground's limit
constexpr int kGait = 10;
constexpr double kSpeedMPerS = 1.2;
constexpr double kYawRateRadPerS = 1.2;

struct TurnOutcome {
  bool slippery = false;           // the watch's verdict at the end
  bool responding = false;         // the controller acting on it at the end
  double ramped_yaw_rate = 0.0;    // the command after the ramp and the clamps, at the end
  bool upright = true;
};

TurnOutcome turn_on_floor(double friction) {
  WalkingSim sim(std::make_unique<qp::GoldfarbIdnaniSolver>(), responding());
  if (friction > 0.0)
    for (std::size_t leg = 0; leg < kNumLegs; ++leg) sim.backend.set_foot_friction(leg, friction);
  sim.controller.set(walk_command(kGait, kSpeedMPerS, 0.0, kYawRateRadPerS));
  TurnOutcome outcome;
  sim.run_until(kStart);
  sim.run_until(kStart + 12.0, [&](const CycleRecord&) { outcome.upright &= sim.upright(); });
  const LocomotionController& walker = sim.controller.walker();
  outcome.slippery = walker.slip_watch().slippery();
  outcome.responding = walker.responding_to_slip();
  outcome.ramped_yaw_rate = walker.ramped_velocity().z();
  return outcome;
}

TEST(SlipResponse, OnAFloorOfFrictionPointThreeTheTurnIsWidenedToTheSlipperyCentripetalLimit) {
  const LocomotionConfig config = responding();
  const TurnOutcome outcome = turn_on_floor(kSlipperyFloorFriction);
  EXPECT_TRUE(outcome.slippery);
  EXPECT_TRUE(outcome.responding);
  // the clamp lowers the yaw rate, never the speed
  EXPECT_NEAR(outcome.ramped_yaw_rate, config.slippery_centripetal_accel_m_s2 / kSpeedMPerS, 1e-9);
  EXPECT_TRUE(outcome.upright);
}

TEST(SlipResponse, OnTheModelsFloorTheGroundStaysClearAndTheTurnIsAsCommanded) {
  const TurnOutcome outcome = turn_on_floor(0.0);  // 0: the model's own friction
  EXPECT_FALSE(outcome.slippery);
  EXPECT_FALSE(outcome.responding);
  EXPECT_NEAR(outcome.ramped_yaw_rate, kYawRateRadPerS, 1e-9);
  EXPECT_TRUE(outcome.upright);
}

TEST(SlipResponse, OnASlipperyGroundTheCommandChangesAtTheSlipperyShareOfTheRamp) {
  const LocomotionConfig config = responding();
  WalkingSim sim(std::make_unique<qp::GoldfarbIdnaniSolver>(), config);
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) sim.backend.set_foot_friction(leg, kSlipperyFloorFriction);
  sim.controller.set(walk_command(kGait, kSpeedMPerS, 0.0, kYawRateRadPerS));
  sim.run_until(kStart + 12.0);
  const LocomotionController& walker = sim.controller.walker();
  ASSERT_TRUE(walker.responding_to_slip());
  // slower: the ramp's step per tick is the slippery share of the product's
  sim.controller.set(walk_command(kGait, kSpeedMPerS - 0.4, 0.0, kYawRateRadPerS));
  const double before_m_s = walker.ramped_velocity().x();
  constexpr int kTicks = 50;
  sim.run_until(kStart + 12.0 + kTicks * config.tick_s);
  ASSERT_TRUE(walker.responding_to_slip());
  const double step_per_tick_m_s = (before_m_s - walker.ramped_velocity().x()) / kTicks;
  EXPECT_NEAR(step_per_tick_m_s, config.max_accel_m_s2 * config.slippery_ramp_share * config.tick_s, 1e-9);
}

}  // namespace
}  // namespace cerebellum
