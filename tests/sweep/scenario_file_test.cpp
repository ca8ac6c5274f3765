// The scenario file's refusals name the file, the key and what is accepted; a good file reads
// into the scenario and its axes.
#include "sweep/scenario_file.hpp"

#include <gtest/gtest.h>

#include <string>

namespace cerebellum {
namespace {

constexpr const char* kGood = R"(
robot:
  sensor_noise: true
seed: 7
duration_s: 8
commands:
  - {at_s: 0, mode: 12}
  - {at_s: 3, mode: 11, gait: 3, vx_m_s: 0.2}
pushes:
  - {at_s: 5, impulse_n_s: 10, direction_deg: 90}
faults:
  - {at_s: 6, fault: motor 3 stuck, duration_s: 1}
settle_speed_m_s: 0.3
sweep:
  push_impulse_n_s: [5, 10, 15]
  seed: [1, 2]
)";

std::string refusal(const std::string& text) {
  try {
    parse_scenario(text, "s.yaml", "");
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "<accepted>";
}

// the file is refused, and the message holds `expected`
void expect_refusal(const std::string& text, const std::string& expected) {
  const std::string e = refusal(text);
  EXPECT_NE(e.find(expected), std::string::npos) << e;
}

TEST(ScenarioFile, AGoodFileReadsIntoTheScenarioAndItsAxesInTheFilesOrder) {
  const SweepSpec spec = parse_scenario(kGood, "s.yaml", "");
  EXPECT_TRUE(spec.base.sensor_noise);
  EXPECT_EQ(spec.base.seed, 7u);
  EXPECT_DOUBLE_EQ(spec.base.duration_s, 8.0);
  ASSERT_EQ(spec.base.commands.size(), 2u);
  EXPECT_EQ(spec.base.commands[1].mode, 11);
  EXPECT_EQ(spec.base.commands[1].gait, 3);
  EXPECT_DOUBLE_EQ(spec.base.commands[1].vx_m_s, 0.2);
  ASSERT_EQ(spec.base.pushes.size(), 1u);
  EXPECT_DOUBLE_EQ(spec.base.pushes[0].direction_deg, 90.0);
  EXPECT_DOUBLE_EQ(spec.base.pushes[0].length_s, 0.1);
  ASSERT_EQ(spec.base.faults.size(), 1u);
  EXPECT_DOUBLE_EQ(spec.base.faults[0].request.duration_s, 1.0);
  ASSERT_EQ(spec.axes.size(), 2u);
  EXPECT_EQ(spec.axes[0].name, "push_impulse_n_s");
  EXPECT_EQ(spec.axes[1].name, "seed");
  EXPECT_EQ(spec.axes[1].values, (std::vector<double>{1, 2}));
}

TEST(ScenarioFile, MalformedYamlIsRefusedNamingTheFile) {
  expect_refusal("duration_s: [1, 2", "scenario s.yaml: not valid YAML");
}

TEST(ScenarioFile, AnUnknownKeyIsRefusedWithTheAcceptedOnes) {
  expect_refusal("duration_s: 3\ncommands: [{at_s: 0, mode: 12}]\nduraton: 4\n",
                 "scenario s.yaml: <top>.duraton is not a known key (accepted: commands,");
}

TEST(ScenarioFile, AnAxisWithNoValuesIsRefused) {
  expect_refusal("duration_s: 3\ncommands: [{at_s: 0, mode: 12}]\nsweep:\n  seed: []\n",
                 "sweep.seed has no values; give at least one");
}

TEST(ScenarioFile, AnUnknownAxisIsRefusedWithTheAxesThatExist) {
  expect_refusal("duration_s: 3\ncommands: [{at_s: 0, mode: 12}]\nsweep:\n  friction: [1]\n",
                 "sweep.friction is not a known key (accepted: gait, push_at_s, push_direction_deg, "
                   "push_impulse_n_s, seed, terrain)");
}

TEST(ScenarioFile, APushAxisWithoutPushesIsRefused) {
  expect_refusal("duration_s: 3\ncommands: [{at_s: 0, mode: 12}]\nsweep:\n  push_impulse_n_s: [5, 10]\n",
                 "sweep.push_impulse_n_s sets a field of every push, but the scenario has no pushes");
}

TEST(ScenarioFile, AnAxisValueOutOfRangeNamesItsIndex) {
  expect_refusal("duration_s: 3\ncommands: [{at_s: 0, mode: 12}]\npushes: [{at_s: 1, impulse_n_s: 5}]\n"
      "sweep:\n  push_impulse_n_s: [5, -1]\n",
                 "sweep.push_impulse_n_s[1] must be in [0");
}

TEST(ScenarioFile, AnUnknownModeIsRefusedWithTheModes) {
  expect_refusal("duration_s: 3\ncommands: [{at_s: 0, mode: 13}]\n",
                 "commands[0].mode must be one of the modes 0, 3, 7");
}

TEST(ScenarioFile, AWalkingCommandWithAGaitNotInTheTableIsRefused) {
  expect_refusal("duration_s: 3\ncommands: [{at_s: 0, mode: 11, gait: 99}]\n",
                 "commands[0].gait is not a gait of the gait table");
}

TEST(ScenarioFile, CommandsOutOfTimeOrderAreRefused) {
  expect_refusal("duration_s: 9\ncommands: [{at_s: 3, mode: 12}, {at_s: 1, mode: 7}]\n",
                 "commands[1].at_s is earlier than the command before it");
}

TEST(ScenarioFile, ACommandAfterTheEndIsRefused) {
  expect_refusal("duration_s: 3\ncommands: [{at_s: 5, mode: 12}]\n",
                 "commands[0].at_s must be in [0, 3]");
}

TEST(ScenarioFile, AFaultOutsideTheGrammarIsRefusedWithTheGrammarsReason) {
  expect_refusal("duration_s: 3\ncommands: [{at_s: 0, mode: 12}]\nfaults: [{at_s: 1, fault: motor 3 melted}]\n",
                 "faults[0].fault ");
}

TEST(ScenarioFile, NeitherScriptNorSoakIsRefused) {
  expect_refusal("duration_s: 3\n", "commands is missing: give a command script (commands:) or a soak (soak:)");
}

TEST(ScenarioFile, AMissingDurationIsRefused) {
  expect_refusal("commands: [{at_s: 0, mode: 12}]\n", "duration_s is missing");
}

TEST(ScenarioFile, ATerrainIsReadAsTheSimulationReadsItAndABadOneIsRefusedWithTheReason) {
  const SweepSpec spec =
      parse_scenario("duration_s: 3\ncommands: [{at_s: 0, mode: 12}]\nterrain: stairs:0.05:0.28\n", "s.yaml", "");
  ASSERT_TRUE(spec.base.terrain.has_value());
  EXPECT_EQ(spec.base.terrain->kind, TerrainKind::Stairs);
  EXPECT_DOUBLE_EQ(spec.base.terrain->stair_rise_m, 0.05);
  EXPECT_DOUBLE_EQ(spec.base.terrain->stair_run_m, 0.28);
  EXPECT_FALSE(parse_scenario("duration_s: 3\ncommands: [{at_s: 0, mode: 12}]\n", "s.yaml", "").base.terrain)
      << "unset: the configuration's";
  const SweepSpec file = parse_scenario("duration_s: 3\ncommands: [{at_s: 0, mode: 12}]\nterrain: file:ground.yaml\n",
                                        "/x/sweeps/s.yaml", "/x/sweeps");
  EXPECT_EQ(file.base.terrain->file, "/x/sweeps/ground.yaml") << "beside the scenario file";
  expect_refusal("duration_s: 3\ncommands: [{at_s: 0, mode: 12}]\nterrain: stairs\n", "scenario s.yaml: terrain ");
  expect_refusal("duration_s: 3\ncommands: [{at_s: 0, mode: 12}]\nterrain: [flat]\n", "terrain must be a string");
}

TEST(ScenarioFile, ATerrainAxisRefusesABadSpecAndACommaNamingTheEntry) {
  const std::string head = "duration_s: 3\ncommands: [{at_s: 0, mode: 12}]\nsweep:\n  terrain: ";
  expect_refusal(head + "[flat, 'stairs:0.1']\n", "sweep.terrain[1] terrain 'stairs:0.1'");
  expect_refusal(head + "['file:a,b.yaml']\n", "sweep.terrain[0] may not hold a comma");
  expect_refusal(head + "[]\n", "sweep.terrain has no values");
  expect_refusal(head + "flat\n", "sweep.terrain must be a list of terrain specs");
  const SweepSpec spec = parse_scenario(head + "['file:ground.yaml']\n", "/x/s.yaml", "/x");
  EXPECT_EQ(spec.axes[0].terrains[0].file, "/x/ground.yaml") << "beside the scenario file";
}

TEST(ScenarioFile, ASoakWithHoldsTheWrongWayRoundIsRefused) {
  expect_refusal("duration_s: 30\nsoak: {hold_min_s: 3, hold_max_s: 1}\n",
                 "soak.hold_max_s is below hold_min_s");
}

TEST(ScenarioFile, ARelativeRobotConfigIsTakenRelativeToTheFile) {
  const SweepSpec spec =
      parse_scenario("robot: {config: ../config/a.yaml}\nduration_s: 3\ncommands: [{at_s: 0, mode: 12}]\n",
                     "/x/sweeps/s.yaml", "/x/sweeps");
  EXPECT_EQ(spec.base.config_path, "/x/config/a.yaml");
}

TEST(ScenarioFile, AFolderIsRefusedAsAFile) {
  try {
    load_scenario("/tmp");
    FAIL() << "a folder was accepted";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("is a folder"), std::string::npos);
  }
}

}  // namespace
}  // namespace cerebellum
