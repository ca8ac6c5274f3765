// The grid: every combination once, the last axis fastest, each cell's values applied to the
// scenario; a hostile product saturates instead of overflowing.
#include "sweep/sweep_grid.hpp"

#include <gtest/gtest.h>

#include <set>

#include "sweep/result_row.hpp"
#include "sweep/scenario_file.hpp"

namespace cerebellum {
namespace {

SweepSpec spec_of(const std::string& sweep) {
  return parse_scenario(
      "duration_s: 9\ncommands: [{at_s: 0, mode: 12}, {at_s: 3, mode: 11, gait: 3}]\n"
      "pushes: [{at_s: 5, impulse_n_s: 1}, {at_s: 6, impulse_n_s: 2}]\nsweep:\n" +
          sweep,
      "s.yaml", "");
}

TEST(SweepGrid, WithoutAxesTheGridIsTheOneBaseScenario) {
  const SweepSpec spec = parse_scenario("duration_s: 3\ncommands: [{at_s: 0, mode: 12}]\n", "s.yaml", "");
  EXPECT_EQ(grid_size(spec), 1u);
  EXPECT_TRUE(cell_values(spec, 0).empty());
}

TEST(SweepGrid, EveryCombinationAppearsOnceWithTheLastAxisFastest) {
  const SweepSpec spec = spec_of("  seed: [1, 2]\n  push_direction_deg: [0, 90, 180]\n");
  ASSERT_EQ(grid_size(spec), 6u);
  EXPECT_EQ(cell_values(spec, 0), (std::vector<double>{1, 0}));
  EXPECT_EQ(cell_values(spec, 1), (std::vector<double>{1, 90}));
  EXPECT_EQ(cell_values(spec, 3), (std::vector<double>{2, 0}));
  std::set<std::vector<double>> seen;
  for (std::uint64_t k = 0; k < 6; ++k) seen.insert(cell_values(spec, k));
  EXPECT_EQ(seen.size(), 6u);
}

TEST(SweepGrid, ACellsValuesAreAppliedToTheSeedEveryPushAndEveryWalkingCommand) {
  const SweepSpec spec = spec_of("  seed: [4]\n  gait: [10]\n  push_impulse_n_s: [12]\n  push_at_s: [5.5]\n");
  const Scenario s = cell_scenario(spec, 0);
  EXPECT_EQ(s.seed, 4u);
  EXPECT_EQ(s.commands[0].gait, 0);  // the stand-up is not a walking command
  EXPECT_EQ(s.commands[1].gait, 10);
  for (const ScenarioPush& p : s.pushes) {
    EXPECT_DOUBLE_EQ(p.impulse_n_s, 12.0);
    EXPECT_DOUBLE_EQ(p.at_s, 5.5);
  }
}

TEST(SweepGrid, ATerrainAxisGivesEachCellItsGroundAndTheResultsNameItsSpec) {
  const SweepSpec spec = spec_of("  terrain: [flat, 'slope:10', 'step:0.04']\n  seed: [1, 2]\n");
  ASSERT_EQ(grid_size(spec), 6u);
  ASSERT_EQ(spec.axes[0].kind, AxisKind::Terrain);
  // cell 3: the second terrain (the seed, last, varies fastest), seed 2
  const Scenario cell = cell_scenario(spec, 3);
  ASSERT_TRUE(cell.terrain.has_value());
  EXPECT_EQ(cell.terrain->kind, TerrainKind::Slope);
  EXPECT_DOUBLE_EQ(cell.terrain->slope_deg, 10.0);
  EXPECT_EQ(cell.seed, 2u);
  EXPECT_EQ(cell_scenario(spec, 5).terrain->kind, TerrainKind::Step);
  EXPECT_EQ(axis_value(spec.axes[0], cell_values(spec, 3)[0]), "slope:10");
  EXPECT_EQ(result_header(spec).rfind("cell,terrain,seed,", 0), 0u) << result_header(spec);
  EXPECT_EQ(result_row(spec, 3, RunResult{}).rfind("3,slope:10,2,", 0), 0u) << result_row(spec, 3, RunResult{});
}

TEST(SweepGrid, AJumpOrMotionIdAxisSetsTheGaitIdOfEveryJumpAndMotionButNotOfTheWalks) {
  const SweepSpec spec = parse_scenario("duration_s: 20\ncommands:\n  - {at_s: 0, mode: 12}\n"
                                        "  - {at_s: 3, mode: 16, gait: 4}\n  - {at_s: 6, mode: 11, gait: 3}\n"
                                        "  - {at_s: 9, mode: 62, gait: 2}\nsweep:\n  jump_or_motion_id: [1, 6]\n",
                                        "s.yaml", "");
  const Scenario s = cell_scenario(spec, 1);
  EXPECT_EQ(s.commands[0].gait, 0);
  EXPECT_EQ(s.commands[1].gait, 6);
  EXPECT_EQ(s.commands[2].gait, 3);
  EXPECT_EQ(s.commands[3].gait, 6);
  EXPECT_EQ(result_header(spec).rfind("cell,jump_or_motion_id,seed,", 0), 0u) << result_header(spec);
}

TEST(SweepGrid, ACellOutsideTheGridIsRefused) {
  const SweepSpec spec = spec_of("  seed: [1, 2]\n");
  EXPECT_THROW(cell_values(spec, 2), std::out_of_range);
}

TEST(SweepGrid, AProductBeyondTheCapSaturatesInsteadOfOverflowing) {
  SweepSpec spec = spec_of("  seed: [1]\n");
  Axis huge;
  huge.values.assign(1u << 20, 1.0);
  spec.axes = {huge, huge, huge, huge};  // 2^80 combinations
  EXPECT_EQ(grid_size(spec), kGridSizeCap);
}

}  // namespace
}  // namespace cerebellum
