// The shipped back flip played open loop on the simulated robot (the motors' law and limits at
// the physics rate), judged on the simulator's truth. It does not land yet (docs/jumps.md,
// "Flips"): this test holds what it does achieve, so that a change that loses it is seen, and the
// MC keeps refusing 16/20 until a played flip lands (McJumps.*Flip*).
#include <gtest/gtest.h>

#include <string>

#include "control/jump/flip_trajectory.hpp"
#include "core/robot_model.hpp"
#include "flip_playback_run.hpp"

namespace cerebellum {
namespace {

TEST(BackFlipPlayback, ThePlannedFlipTurnsTheTrunkPastHalfATurnWithinTheMotorsLimits) {
  std::string error;
  const auto trajectory =
      read_flip_trajectory(std::string(CEREBELLUM_SOURCE_DIR) + "/config/flips/back_flip.csv", robot::kTorqueMaxNm, error);
  ASSERT_TRUE(trajectory.has_value()) << error;
  FlipPlaybackSetup setup;
  setup.model_path = std::string(CEREBELLUM_MODEL_DIR) + "/cyberdog2.xml";
  const FlipPlaybackOutcome outcome = play_flip_on_simulation(*trajectory, setup);
  // measured -3.59 rad by the plan's end (57 % of the planned -2 pi); the jump controller's best
  // push reached 1.9 rad
  EXPECT_LT(outcome.pitch_at_plan_end_rad, -3.3);
  EXPECT_LE(outcome.peak_torque_nm, robot::kTorqueMaxNm + 1e-9);
}

}  // namespace
}  // namespace cerebellum
