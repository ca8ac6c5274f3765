// The whole MC walking blind over the generated terrains (backend/terrain) in lockstep, judged on
// the simulator's truth: what it crosses today, kept from regressing. The client holds the heading
// on the robot's own yaw estimate (loop/heading_hold_walk). Figures over 20 fresh seeds, and what
// it does not cross yet, are in docs/terrain.md (bench/terrain_bench).
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "loop/heading_hold_walk.hpp"
#include "loop/simulated_robot.hpp"
#include "sweep/random_soak.hpp"

namespace cerebellum {
namespace {

struct Crossing {
  bool crossed = false;
  bool stayed_upright = true;
  double lowest_above_ground_m = 1.0;  // the trunk over the ground under it
  double time_s = 0.0;
  double highest_ground_m = 0.0;  // the terrain under the trunk, as sim_truth reports it
};

// the MC beyond the product for steps, as shipped (config/extended-terrain.yaml)
McConfig extended_terrain_config() {
  return load_config(std::string(CEREBELLUM_SOURCE_DIR) + "/config/extended-terrain.yaml");
}

// step_height_m < 0: the gait's own
Crossing walk_across(const std::string& terrain, double speed_m_s, double to_x_m, double seconds, unsigned seed,
                     McConfig config = default_config(), double step_height_m = -1.0) {
  config.startup = Startup::Off;
  config.robot.terrain = parse_terrain_spec(terrain);
  config.robot.noise.enabled = true;
  config.robot.noise.seed = seed;
  Mc mc = make_simulated_mc(config);
  LockstepClient(mc).run(high_level_command(ModeId::RecoveryStand, 0), 3.0);
  Crossing out;
  HighLevelCommand command = high_level_command(ModeId::Locomotion, kSlowTrotGaitId, speed_m_s);
  if (step_height_m >= 0.0) command.step_height = {static_cast<float>(step_height_m), static_cast<float>(step_height_m)};
  HeadingHoldWalk walk(mc, command);
  out.time_s = walk.run(seconds, [&](const CycleRecord&) {
    const GroundTruth truth = mc.simulation().ground_truth();
    out.stayed_upright = out.stayed_upright && upright(truth);
    out.lowest_above_ground_m = std::min(out.lowest_above_ground_m, truth.position[2] - truth.ground_height_m);
    out.highest_ground_m = std::max(out.highest_ground_m, truth.ground_height_m);
    out.crossed = truth.position[0] >= to_x_m;
    return !out.crossed && out.stayed_upright;
  });
  return out;
}

TEST(McTerrainWalk, TheSlowTrotWalksUpAndDownATenDegreeSlopeAtFourTenthsOfAMetrePerSecond) {
  const Crossing c = walk_across("slope:10", 0.4, 10.0, 35.0, 7);
  EXPECT_TRUE(c.stayed_upright);
  EXPECT_TRUE(c.crossed) << "after " << c.time_s << " s";
  EXPECT_GT(c.highest_ground_m, 0.5) << "it went over the top (3 m of 10 degrees: 0.53 m up)";
  EXPECT_GT(c.lowest_above_ground_m, 0.15);
}

TEST(McTerrainWalk, TheSlowTrotStepsUpAndDownAFourCentimetreStep) {
  const Crossing c = walk_across("step:0.04", 0.3, 4.0, 20.0, 7);
  EXPECT_TRUE(c.stayed_upright);
  EXPECT_TRUE(c.crossed) << "after " << c.time_s << " s";
  EXPECT_DOUBLE_EQ(c.highest_ground_m, 0.04);
}

// blind: the swing meets the step's top early (held there), aims at the ground it lifted from, and
// reaches down off the far edge (LocomotionConfig's early and late touchdown)
TEST(McTerrainWalk, TheExtendedTerrainConfigurationStepsUpAndDownAnEightCentimetreStepWithATenCentimetreSwing) {
  const Crossing c = walk_across("step:0.08", 0.3, 4.0, 20.0, 7, extended_terrain_config(), 0.10);
  EXPECT_TRUE(c.stayed_upright);
  EXPECT_TRUE(c.crossed) << "after " << c.time_s << " s";
  EXPECT_DOUBLE_EQ(c.highest_ground_m, 0.08);
  EXPECT_GT(c.lowest_above_ground_m, 0.12);
}

TEST(McTerrainWalk, TheSlowTrotCrossesTwentyMetresOfThreeCentimetreRoughGroundAtHalfAMetrePerSecond) {
  const Crossing c = walk_across("rough:0.03:7", 0.5, 21.0, 50.0, 7);
  EXPECT_TRUE(c.stayed_upright);
  EXPECT_TRUE(c.crossed) << "after " << c.time_s << " s";
  EXPECT_GT(c.lowest_above_ground_m, 0.12);
}

}  // namespace
}  // namespace cerebellum
