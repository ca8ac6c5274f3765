// Gait 4, the passive trot, in simulation: it stands while nothing moves it, trots along a steady
// pull on the trunk (a leash), stands again soon after the pull stops, and still walks when
// commanded. Judged on the simulator's truth (trunk position, true foot contacts).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "control/locomotion/gait_table.hpp"
#include "modes/mode_sim.hpp"

namespace cerebellum {
namespace {

using testing::command;
using testing::ModeSim;

HighLevelCommand passive_trot(float vx = 0.0f) {
  HighLevelCommand c = command(ModeId::Locomotion, kPassiveTrotGaitId);
  c.vel_des = {vx, 0.0f, 0.0f};
  return c;
}

bool all_feet_down(const ModeSim& sim) {
  const GroundTruth truth = sim.backend.ground_truth();
  return std::all_of(truth.foot_contact.begin(), truth.foot_contact.end(), [](bool c) { return c; });
}

Eigen::Vector2d true_xy(const ModeSim& sim) {
  const GroundTruth truth = sim.backend.ground_truth();
  return {truth.position[0], truth.position[1]};
}

bool upright(const ModeSim& sim) {
  return sim.true_height() > 0.18 && std::abs(sim.true_rpy().x()) < 0.5 && std::abs(sim.true_rpy().y()) < 0.5;
}

// stands up, then enters gait 4 and waits for it to settle
void stand_in_passive_trot(ModeSim& sim) {
  sim.run(3.0);
  sim.send(passive_trot(), 1.5);
  ASSERT_EQ(sim.status().mode, 11);
  ASSERT_EQ(sim.status().gait_id, kPassiveTrotGaitId);
}

// the longest time within `seconds` during which some foot was in the air, and the trunk's travel
struct Watch {
  double longest_lift_s = 0.0;
  bool stayed_up = true;
  double worst_tilt_rad = 0.0;
  double lowest_m = 1.0;
};
Watch watch(ModeSim& sim, double seconds) {
  Watch w;
  double lifted_s = 0.0;
  const double end = sim.time_s() + seconds - 1e-9;
  while (sim.time_s() < end) {
    sim.run(0.002);
    lifted_s = all_feet_down(sim) ? 0.0 : lifted_s + 0.002;
    w.longest_lift_s = std::max(w.longest_lift_s, lifted_s);
    w.stayed_up = w.stayed_up && upright(sim);
    w.worst_tilt_rad = std::max({w.worst_tilt_rad, std::abs(sim.true_rpy().x()), std::abs(sim.true_rpy().y())});
    w.lowest_m = std::min(w.lowest_m, sim.true_height());
  }
  return w;
}

// after a release, for `seconds`: whether it stayed upright throughout, and how long until it stood
// (every foot down, trunk below 0.15 m/s) from then on to the end; -1 when it never did
struct Release {
  bool stayed_up = true;
  double standing_after_s = -1.0;
};
Release watch_release(ModeSim& sim, double seconds) {
  Release r;
  const double release_s = sim.time_s();
  double stood_since_s = -1.0;
  while (sim.time_s() < release_s + seconds - 1e-9) {
    sim.run(0.002);
    const GroundTruth t = sim.backend.ground_truth();
    const bool standing = all_feet_down(sim) && std::hypot(t.velocity_world[0], t.velocity_world[1]) < 0.15;
    if (!standing) stood_since_s = -1.0;
    if (standing && stood_since_s < 0.0) stood_since_s = sim.time_s();
    r.stayed_up = r.stayed_up && upright(sim);
  }
  r.standing_after_s = stood_since_s < 0.0 ? -1.0 : stood_since_s - release_s;
  return r;
}

class PassiveTrotAlone : public ::testing::TestWithParam<unsigned> {};

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

// 0: no sensor noise; else the noise's seed
INSTANTIATE_TEST_SUITE_P(NoiseSeeds, PassiveTrotAlone, ::testing::Values(0u, 11u, 12u));

struct PullCase {
  double fx_n, fy_n;
  unsigned noise_seed;  // 0: no sensor noise
};

class PassiveTrotPull : public ::testing::TestWithParam<PullCase> {};

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

INSTANTIATE_TEST_SUITE_P(FifteenNewtons, PassiveTrotPull,
                         ::testing::Values(PullCase{15.0, 0.0, 0}, PullCase{-15.0, 0.0, 0}, PullCase{0.0, 15.0, 0},
                                           PullCase{15.0, 0.0, 11}, PullCase{0.0, -15.0, 12},
                                           // fresh seeds and directions, not looked at while tuning
                                           PullCase{10.6, 10.6, 31}, PullCase{-10.6, -10.6, 32},
                                           PullCase{-15.0, 0.0, 33}, PullCase{0.0, 15.0, 34},
                                           PullCase{10.6, -10.6, 35}));

// As a client does it (12, then 11/4 as soon as the stand reports bar >= 95): a pull of 1-4 s
// started 0.5-5 s after entering gait 4; released, it stands within 1.5 s every time. With the
// 5 cm steps `cerebellum cmd walk --gait 4` asks for, the trot in place used to keep itself going
// (issue 47: its force estimate stayed above the old 5 N stop threshold)
struct LatePullCase {
  double wait_s;  // after entering gait 4
  double pull_s;
  float step_height_m;  // 0: the gait's own
  unsigned noise_seed;  // 0: no sensor noise
};

class PassiveTrotLatePull : public ::testing::TestWithParam<LatePullCase> {};

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

INSTANTIATE_TEST_SUITE_P(WaitsPullsAndStepHeights, PassiveTrotLatePull,
                         ::testing::Values(LatePullCase{0.5, 1.0, 0.05f, 0}, LatePullCase{0.5, 4.0, 0.05f, 0},
                                           LatePullCase{2.0, 1.0, 0.05f, 0}, LatePullCase{2.0, 3.0, 0.05f, 0},
                                           LatePullCase{5.0, 4.0, 0.05f, 0}, LatePullCase{3.0, 2.0, 0.05f, 41},
                                           LatePullCase{1.0, 3.0, 0.0f, 42}, LatePullCase{5.0, 1.0, 0.0f, 0}));

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
}  // namespace cerebellum
