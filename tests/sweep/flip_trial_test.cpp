// The back flip (16/20) over 20 noisy seeds (501-520, which no tuning decision looked at), each run
// through the whole MC in lockstep and judged on the simulator's truth (sweep/flip_trial): every
// one turns at least 2 pi - 0.3 rad about its pitch axis within the motors' 12 Nm, never falls and
// stands again within 0.5 m of its take-off. A long sweep: the Release stage runs it, the
// sanitized stage leaves it out (label "seeds"); bench/flip_bench tabulates the same runs.
#include <gtest/gtest.h>

#include <cmath>

#include "core/robot_model.hpp"
#include "loop/mc_fixture.hpp"
#include "sweep/flip_trial.hpp"

namespace cerebellum {
namespace {

TEST(FlipTrialSeeds, EveryNoisyBackFlipTurnsAFullTurnWithinTheMotorsLimitsAndStandsNearItsTakeOff) {
  for (unsigned seed = 501; seed <= 520; ++seed) {
    const FlipTrial f = run_back_flip_trial(testing::lying_start(true, seed));
    EXPECT_GE(std::abs(f.turned_rad), 2.0 * robot::kPi - 0.3) << "seed " << seed;
    EXPECT_LE(f.peak_torque_nm, robot::kTorqueMaxNm + 1e-9) << "seed " << seed;
    EXPECT_LT(f.distance_m, 0.5) << "seed " << seed;
    EXPECT_FALSE(f.fell) << "seed " << seed;
    EXPECT_TRUE(f.stood) << "seed " << seed;
  }
}

}  // namespace
}  // namespace cerebellum
