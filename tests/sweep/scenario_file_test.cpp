// The scenario file's refusals name the file, the key and what is accepted; a good file reads
// into the scenario and its axes.
#include "sweep/scenario_file.hpp"

#include <algorithm>
#include <cmath>

#include "core/robot_model.hpp"
#include "sweep/model_error_draw.hpp"

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
                 "sweep.friction is not a known key (accepted: gait, jump_or_motion_id, push_at_s, push_direction_deg, "
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

namespace cerebellum {
namespace {

const std::string kModelErrorHead = "duration_s: 3\ncommands: [{at_s: 0, mode: 12}]\nrobot:\n  sensor_noise: true\n"
                                    "  model_error:\n";

TEST(ScenarioFile, AModelErrorIsReadWithItsRangesInSeconds) {
  const SweepSpec spec = parse_scenario(kModelErrorHead +
                                            "    mass_fraction: 0.15\n    com_offset_m: 0.02\n"
                                            "    foot_friction: [0.4, 1.2]\n    motor_strength_fraction: 0.15\n"
                                            "    actuation_delay_ms: [0, 4]\n    sensor_noise_scale: 2\n",
                                        "s.yaml", "");
  ASSERT_TRUE(spec.base.model_error.has_value());
  const ModelErrorRanges& r = *spec.base.model_error;
  EXPECT_DOUBLE_EQ(r.mass_fraction, 0.15);
  EXPECT_DOUBLE_EQ(r.com_offset_m, 0.02);
  EXPECT_DOUBLE_EQ(r.friction_min, 0.4);
  EXPECT_DOUBLE_EQ(r.friction_max, 1.2);
  EXPECT_DOUBLE_EQ(r.motor_strength_fraction, 0.15);
  EXPECT_DOUBLE_EQ(r.actuation_delay_min_s, 0.0);
  EXPECT_DOUBLE_EQ(r.actuation_delay_max_s, 0.004);
  EXPECT_DOUBLE_EQ(r.sensor_noise_scale, 2.0);
  EXPECT_FALSE(parse_scenario("duration_s: 3\ncommands: [{at_s: 0, mode: 12}]\n", "s.yaml", "").base.model_error)
      << "unset: the exact model";
}

TEST(ScenarioFile, AModelErrorOutOfRangeOrTheWrongWayRoundOrWithoutNoiseToScaleIsRefused) {
  expect_refusal(kModelErrorHead + "    mass_fraction: 0.9\n", "robot.model_error.mass_fraction");
  expect_refusal(kModelErrorHead + "    foot_friction: [1.2, 0.4]\n",
                 "robot.model_error.foot_friction has its high end below its low end");
  expect_refusal(kModelErrorHead + "    foot_friction: [0.4]\n", "robot.model_error.foot_friction must be a range");
  expect_refusal(kModelErrorHead + "    actuation_delay_ms: [0, 40]\n", "robot.model_error.actuation_delay_ms[1]");
  expect_refusal(kModelErrorHead + "    payload_kg: 1\n", "robot.model_error.payload_kg is not a known key");
  expect_refusal("duration_s: 3\ncommands: [{at_s: 0, mode: 12}]\nrobot:\n  model_error: {sensor_noise_scale: 2}\n",
                 "sensor_noise_scale scales the sensor noise: it needs robot.sensor_noise: true");
}

TEST(ScenarioFile, AJumpThatIsNotInTheJumpTableIsRefusedInTheScriptAndOnTheAxis) {
  expect_refusal("duration_s: 8\ncommands: [{at_s: 0, mode: 12}, {at_s: 3, mode: 16, gait: 8}]\n",
                 "commands[1].gait is not a jump id of mode 16 (0, 1, 2, 3, 4, 5, 6, 9, 20, 21)");
  expect_refusal("duration_s: 8\ncommands: [{at_s: 0, mode: 12}, {at_s: 3, mode: 16, gait: 4}]\n"
                 "sweep: {jump_or_motion_id: [4, 7]}\n",
                 "sweep.jump_or_motion_id[1] is not a jump id of mode 16");
  expect_refusal("duration_s: 8\ncommands: [{at_s: 0, mode: 12}]\nsweep: {jump_or_motion_id: [4]}\n",
                 "but the script has none");
}

TEST(ModelErrorDraw, EachRunsDrawStaysWithinItsRangesCoversThemAndRepeatsForItsSeed) {
  ModelErrorRanges ranges;
  ranges.mass_fraction = 0.15;
  ranges.com_offset_m = 0.02;
  ranges.friction_min = 0.4;
  ranges.friction_max = 1.2;
  ranges.motor_strength_fraction = 0.15;
  ranges.actuation_delay_max_s = 0.004;
  double lowest_mass = 1e9, highest_mass = -1e9, lowest_friction = 1e9, highest_friction = -1e9;
  double largest_delay = 0.0, weakest = 1e9;
  for (unsigned seed = 1; seed <= 2000; ++seed) {
    const ModelError e = draw_model_error(ranges, seed);
    ASSERT_LE(std::abs(e.added_mass_kg), 0.15 * robot::kTotalMassKg);
    for (double offset : e.com_offset_m) ASSERT_LE(std::abs(offset), 0.02);
    ASSERT_GE(e.foot_friction, 0.4);
    ASSERT_LE(e.foot_friction, 1.2);
    ASSERT_LE(std::abs(e.motor_strength_scale - 1.0), 0.15);
    ASSERT_GE(e.actuation_delay_s, 0.0);
    ASSERT_LE(e.actuation_delay_s, 0.004);
    lowest_mass = std::min(lowest_mass, e.added_mass_kg);
    highest_mass = std::max(highest_mass, e.added_mass_kg);
    lowest_friction = std::min(lowest_friction, e.foot_friction);
    highest_friction = std::max(highest_friction, e.foot_friction);
    largest_delay = std::max(largest_delay, e.actuation_delay_s);
    weakest = std::min(weakest, e.motor_strength_scale);
  }
  // 2000 uniform draws come within 1 % of each end of a range (a miss has odds below 1e-8)
  EXPECT_LT(lowest_mass, -0.99 * 0.15 * robot::kTotalMassKg);
  EXPECT_GT(highest_mass, 0.99 * 0.15 * robot::kTotalMassKg);
  EXPECT_LT(lowest_friction, 0.408);
  EXPECT_GT(highest_friction, 1.192);
  EXPECT_GT(largest_delay, 0.00396);
  EXPECT_LT(weakest, 0.8515);
  const ModelError a = draw_model_error(ranges, 7), b = draw_model_error(ranges, 7), c = draw_model_error(ranges, 8);
  EXPECT_EQ(a.added_mass_kg, b.added_mass_kg);
  EXPECT_EQ(a.actuation_delay_s, b.actuation_delay_s);
  EXPECT_NE(a.added_mass_kg, c.added_mass_kg);
  EXPECT_FALSE(draw_model_error(ModelErrorRanges{}, 7).any()) << "zero ranges: the exact model";
}

}  // namespace
}  // namespace cerebellum
