// Gait 4, the passive trot, in simulation, the cases with parameters: it stands while nothing
// moves it, trots along a steady pull on the trunk (a leash) and stands again soon after the pull
// stops, however long after entering and however long pulled. Judged on the simulator's truth.
// Each program instantiates them: test_modes_sim one of each (passive_trot_sim_test.cpp), the
// seeds program the rest (passive_trot_seeds_test.cpp).
#include <gtest/gtest.h>

#include <cstdio>

#include "passive_trot_watch.hpp"

namespace cerebellum {
namespace testing {
namespace {

TEST_P(PassiveTrotAlone, StandsStillWhileNothingPullsIt) {
  ModeSim sim(ModeId::RecoveryStand, 0.3, GetParam() != 0, GetParam());
  stand_in_passive_trot(sim);
  const Eigen::Vector2d start = true_xy(sim);
  const Watch w = watch(sim, 6.0);
  EXPECT_TRUE(w.stayed_up);
  // a foot lifted for a moment is a touchdown bounce, not a step (a trot's swing lasts 0.18 s)
  EXPECT_LT(w.longest_lift_s, 0.05);
  EXPECT_LT((true_xy(sim) - start).norm(), 0.03);
  EXPECT_FALSE(sim.modes.passive_trot().follow().following());
}

TEST_P(PassiveTrotPull, FollowsASteadyPullAndStandsWhereItIsLeftAlone) {
  ModeSim sim(ModeId::RecoveryStand, 0.3, GetParam().noise_seed != 0, GetParam().noise_seed);
  stand_in_passive_trot(sim);
  const Eigen::Vector2d pull(GetParam().fx_n, GetParam().fy_n);
  const Eigen::Vector2d start = true_xy(sim);
  // a steady pull of 15 N for 3 s on the trunk, world frame
  sim.backend.request_force_pulse({{pull.x(), pull.y(), 0.0}, 3.0});
  const Watch pulled = watch(sim, 3.0);
  EXPECT_TRUE(pulled.stayed_up);
  const Eigen::Vector2d moved = true_xy(sim) - start;
  const double along_m = moved.dot(pull.normalized());
  EXPECT_GE(along_m, 0.5) << "moved " << moved.transpose();
  std::printf("pulled 3 s: moved %.2f m along the pull, worst tilt %.2f rad, lowest %.3f m\n", along_m,
              pulled.worst_tilt_rad, pulled.lowest_m);
  // it stepped to get there: a planted stand leans but does not travel
  EXPECT_GT(pulled.longest_lift_s, 0.1);

  // released: standing (every foot down from then on, trunk at rest) within 1.5 s of the release
  const Eigen::Vector2d released_at = true_xy(sim);
  const Release released = watch_release(sim, 3.0);
  ASSERT_TRUE(released.stayed_up);
  ASSERT_GE(released.standing_after_s, 0.0) << "still stepping 3 s after the pull stopped";
  EXPECT_LE(released.standing_after_s, 1.5);
  std::printf("released: standing after %.2f s\n", released.standing_after_s);
  EXPECT_FALSE(sim.modes.passive_trot().follow().following());
  // near where it was let go: the trot's last steps, no wandering off
  EXPECT_LT((true_xy(sim) - released_at).norm(), 0.15);
  EXPECT_EQ(sim.status().gait_id, kPassiveTrotGaitId);
}

TEST_P(PassiveTrotLatePull, ReleasedItStandsWithinOneAndAHalfSecondsHoweverLongAfterEnteringAndPulled) {
  const LatePullCase c = GetParam();
  ModeSim sim(ModeId::Off, 0.3, c.noise_seed != 0, c.noise_seed);
  sim.run(0.5);
  sim.send(command(ModeId::RecoveryStand), 0.0);
  ASSERT_GT(sim.run_until([&] { return sim.status().order_process_bar >= 95; }, 10.0), 0.0);
  HighLevelCommand trot = passive_trot();
  trot.step_height = {c.step_height_m, c.step_height_m};
  sim.send(trot, c.wait_s);
  ASSERT_EQ(sim.status().gait_id, kPassiveTrotGaitId);
  sim.backend.request_force_pulse({{15.0, 0.0, 0.0}, c.pull_s});
  const Watch pulled = watch(sim, c.pull_s);
  ASSERT_TRUE(pulled.stayed_up);
  ASSERT_GT(pulled.longest_lift_s, 0.1) << "it did not step along the pull";
  const Release released = watch_release(sim, 3.0);
  ASSERT_TRUE(released.stayed_up);
  ASSERT_GE(released.standing_after_s, 0.0) << "still stepping 3 s after the release";
  EXPECT_LE(released.standing_after_s, 1.5);
  EXPECT_FALSE(sim.modes.passive_trot().follow().following());
}

}  // namespace
}  // namespace testing
}  // namespace cerebellum
