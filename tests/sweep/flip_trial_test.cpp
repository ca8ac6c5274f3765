// The flips over 20 noisy seeds each (the back flip 16/20 on 501-520, the front flip 16/21 on
// 601-620; no tuning decision looked at either set), each run through the whole MC in lockstep
// and judged on the simulator's truth (sweep/flip_trial): every one turns at least 2 pi - 0.3 rad
// about its pitch axis, nose up for the back flip and nose down for the front flip, within the
// motors' 12 Nm, never falls and stands again within 0.5 m of its take-off. A long sweep: the
// Release stage runs it, the sanitized stage leaves it out (label "seeds"); bench/flip_bench
// tabulates the same runs.
#include <gtest/gtest.h>

#include <cmath>

#include "core/robot_model.hpp"
#include "loop/mc_fixture.hpp"
#include "modes/jump_mode.hpp"
#include "sweep/flip_trial.hpp"

namespace cerebellum {
namespace {

// sign: the SDK's pitch sense of the turn (nose up, a back flip, is negative)
void expect_every_seed_flips_and_stands(int flip_gait_id, double sign, unsigned first_seed, unsigned last_seed) {
  for (unsigned seed = first_seed; seed <= last_seed; ++seed) {
    const FlipTrial f = run_flip_trial(testing::lying_start(true, seed), flip_gait_id);
    EXPECT_GE(sign * f.turned_rad, 2.0 * robot::kPi - 0.3) << "seed " << seed;
    EXPECT_LE(f.peak_torque_nm, robot::kTorqueMaxNm + 1e-9) << "seed " << seed;
    EXPECT_LT(f.distance_m, 0.5) << "seed " << seed;
    EXPECT_FALSE(f.fell) << "seed " << seed;
    EXPECT_TRUE(f.stood) << "seed " << seed;
  }
}

TEST(FlipTrialSeeds, EveryNoisyBackFlipTurnsAFullTurnWithinTheMotorsLimitsAndStandsNearItsTakeOff) {
  expect_every_seed_flips_and_stands(kBackFlipGaitId, -1.0, 501, 520);
}

TEST(FlipTrialSeeds, EveryNoisyFrontFlipTurnsAFullTurnWithinTheMotorsLimitsAndStandsNearItsTakeOff) {
  expect_every_seed_flips_and_stands(kFrontFlipGaitId, 1.0, 601, 620);
}

}  // namespace
}  // namespace cerebellum
