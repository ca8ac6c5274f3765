// The shipped back flip played open loop on the simulated robot (the motors' law and limits at
// the physics rate, one command per 2 ms), judged on the simulator's truth: the targets
// for the flip itself (docs/jumps.md, "Flips"). The MC does not play it yet: 16/20 stays refused
// there until its mode plays this file (McJumps.*Flip*).
#include <gtest/gtest.h>

#include <string>

#include "control/jump/flip_trajectory.hpp"
#include "core/robot_model.hpp"
#include "flip_playback_run.hpp"

namespace cerebellum {
namespace {

TEST(BackFlipPlayback, ThePlannedFlipTurnsTheTrunkAFullTurnWithinTheMotorsLimitsAndLandsUprightNearTheTakeOff) {
  std::string error;
  const auto trajectory =
      read_flip_trajectory(std::string(CEREBELLUM_SOURCE_DIR) + "/config/flips/back_flip.csv", robot::kTorqueMaxNm, error);
  ASSERT_TRUE(trajectory.has_value()) << error;
  FlipPlaybackSetup setup;
  setup.model_path = std::string(CEREBELLUM_MODEL_DIR) + "/cyberdog2.xml";
  const FlipPlaybackOutcome outcome = play_flip_on_simulation(*trajectory, setup);
  // measured: -6.24 rad in all, 0.38 m from the take-off (seed 0)
  EXPECT_LT(outcome.pitch_turned_rad, -(2.0 * robot::kPi - 0.3));
  EXPECT_LE(outcome.peak_torque_nm, robot::kTorqueMaxNm + 1e-9);
  EXPECT_TRUE(outcome.landed_upright);
  EXPECT_LT(outcome.landing_distance_m, 0.5);
}

}  // namespace
}  // namespace cerebellum
