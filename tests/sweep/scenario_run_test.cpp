// One run of a scenario in lockstep: the same cell gives the same result (the sweep's promise
// that a cell's row does not depend on where or when it ran), a hard shove is judged a fall on
// the simulator's truth, and the soak sends its commands and faults.
#include "sweep/scenario_run.hpp"

#include <gtest/gtest.h>

#include "sweep/result_row.hpp"
#include "sweep/scenario_file.hpp"
#include "sweep/sweep_grid.hpp"

namespace cerebellum {
namespace {

constexpr const char* kStandAndShove = R"(
duration_s: 6
commands:
  - {at_s: 0, mode: 12}
  - {at_s: 3, mode: 11, gait: 1}
pushes:
  - {at_s: 4, impulse_n_s: 0, direction_deg: 90}
sweep:
  push_impulse_n_s: [0, 80]
)";

TEST(ScenarioRun, TheSameCellGivesTheSameRowTwice) {
  const SweepSpec spec = parse_scenario(kStandAndShove, "s.yaml", "");
  const std::string first = result_row(spec, 0, run_scenario(cell_scenario(spec, 0)));
  const std::string second = result_row(spec, 0, run_scenario(cell_scenario(spec, 0)));
  EXPECT_EQ(first, second);
}

TEST(ScenarioRun, TheScenariosTerrainReplacesTheConfigurationsAndItsAbsenceKeepsIt) {
  SweepSpec spec = parse_scenario(std::string(kStandAndShove) + "terrain: step:0.04\n", "s.yaml", "");
  const McConfig stepped = scenario_config(cell_scenario(spec, 0));
  EXPECT_EQ(stepped.robot.terrain.kind, TerrainKind::Step);
  EXPECT_DOUBLE_EQ(stepped.robot.terrain.step_height_m, 0.04);
  spec = parse_scenario(kStandAndShove, "s.yaml", "");
  EXPECT_EQ(scenario_config(cell_scenario(spec, 0)).robot.terrain.kind, default_config().robot.terrain.kind);
}

TEST(ScenarioRun, StandingUnpushedEndsOkAndAHardShoveIsJudgedAFall) {
  const SweepSpec spec = parse_scenario(kStandAndShove, "s.yaml", "");
  const RunResult calm = run_scenario(cell_scenario(spec, 0));
  EXPECT_EQ(calm.outcome, "ok");
  EXPECT_EQ(calm.falls, 0);
  EXPECT_EQ(calm.end_mode, 11);
  EXPECT_EQ(calm.pushes, 1);
  EXPECT_EQ(calm.commands, 2);
  EXPECT_NEAR(calm.robot_time_s, 6.0, 0.003);
  const RunResult shoved = run_scenario(cell_scenario(spec, 1));
  EXPECT_EQ(shoved.outcome, "fell") << "max tilt " << shoved.max_tilt_deg << " deg";
  EXPECT_GE(shoved.first_fall_s, 4.0);
  EXPECT_EQ(shoved.falls_not_safe, 0);
}

TEST(ScenarioRun, ANamedMotionThatFinishesInItsLevelStandIsOkAndAJumpLandsWhereItAimed) {
  const SweepSpec spec = parse_scenario("duration_s: 8\ncommands: [{at_s: 0, mode: 12}, {at_s: 3, mode: 62, gait: 3}]\n"
                                        "settle_speed_m_s: 0.3\nsweep: {jump_or_motion_id: [3]}\n",
                                        "s.yaml", "");
  const RunResult sat = run_scenario(cell_scenario(spec, 0));
  EXPECT_EQ(sat.end_mode, static_cast<int>(ModeId::PoseControl)) << "the motion's last step";
  EXPECT_EQ(sat.outcome, "ok");
  const SweepSpec jump = parse_scenario("duration_s: 8\ncommands: [{at_s: 0, mode: 12}, {at_s: 3, mode: 16, gait: 4}]\n"
                                        "settle_speed_m_s: 0.3\n",
                                        "s.yaml", "");
  const RunResult jumped = run_scenario(cell_scenario(jump, 0));
  EXPECT_EQ(jumped.outcome, "ok");
  EXPECT_NEAR(jumped.distance_m, 0.30, 0.05) << "16/4: 30 cm forward";
}

TEST(ScenarioRun, ABackFlipsOwnTurnIsNotAFallAndItEndsStandingBehindItsTakeOff) {
  const SweepSpec spec = parse_scenario("duration_s: 9\ncommands: [{at_s: 0, mode: 12}, {at_s: 3, mode: 16, gait: 20}]\n"
                                        "settle_speed_m_s: 0.3\n",
                                        "s.yaml", "");
  const RunResult flip = run_scenario(cell_scenario(spec, 0));
  EXPECT_GT(flip.max_tilt_deg, 170.0) << "it turned over";
  EXPECT_EQ(flip.falls, 0);
  EXPECT_EQ(flip.outcome, "ok");
  EXPECT_NEAR(flip.distance_m, 0.37, 0.1) << "docs/jumps.md: it stands 0.37 m behind its take-off";
}

TEST(ScenarioRun, TheSoakSendsRandomCommandsAndFaultsAndJudgesSafety) {
  const SweepSpec spec = parse_scenario("robot: {sensor_noise: true}\nseed: 3\nduration_s: 15\n"
                                            "commands: [{at_s: 0, mode: 12}]\nsoak: {start_s: 3, fault_chance: 1}\n",
                                        "s.yaml", "");
  const RunResult r = run_scenario(spec.base);
  EXPECT_GE(r.commands, 1 + 3);  // the stand-up, then a command every 1-3 s (more with stand-ups after a stop)
  EXPECT_GE(r.faults, 2);  // a fault before every command; a stop is followed by a 8.6 s stand-up
  EXPECT_EQ(r.non_finite_commands, 0);
  EXPECT_EQ(r.falls_not_safe, 0);
  EXPECT_GE(r.robot_time_s, 15.0);
}

}  // namespace
}  // namespace cerebellum
