// Gait 4, the passive trot, in simulation: one of each case with parameters (the rest, seeded,
// in passive_trot_seeds_test.cpp, left out of the sanitized stage), and it still walks when
// commanded. Judged on the simulator's truth (trunk position, true foot contacts).
#include <gtest/gtest.h>

#include "passive_trot_watch.hpp"

namespace cerebellum {
namespace testing {
namespace {

INSTANTIATE_TEST_SUITE_P(NoNoise, PassiveTrotAlone, ::testing::Values(0u));
INSTANTIATE_TEST_SUITE_P(FifteenNewtonsForward, PassiveTrotPull, ::testing::Values(PullCase{15.0, 0.0, 0}));
INSTANTIATE_TEST_SUITE_P(LongestPullSoonAfterEntering, PassiveTrotLatePull,
                         ::testing::Values(LatePullCase{0.5, 4.0, 0.05f, 0}));

TEST(PassiveTrotSim, CommandedVelocityStillWalksIt) {
  ModeSim sim;
  stand_in_passive_trot(sim);
  const Eigen::Vector2d start = true_xy(sim);
  sim.send(passive_trot(0.3f), 3.0);
  const Eigen::Vector2d moved = true_xy(sim) - start;
  EXPECT_TRUE(upright(sim));
  EXPECT_GT(moved.x(), 0.5);
  // the command stops: it stands again
  sim.send(passive_trot(0.0f), 2.0);
  EXPECT_FALSE(sim.modes.passive_trot().follow().following());
  const Watch after = watch(sim, 1.0);
  EXPECT_LT(after.longest_lift_s, 0.05);
}

}  // namespace
}  // namespace testing
}  // namespace cerebellum
