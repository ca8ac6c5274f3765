// Gait 110 in simulation: an uploaded user gait (definition + parameters, in the seed's format)
// runs once on the walking controller. The feet follow the definition's contact pattern (checked
// per section on the simulator's feet), the body follows the steps' velocity, the robot stays up
// and ends standing; the progress bar is the elapsed share of the total time.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

#include "motions/user_gait_convert.hpp"
#include "motions/user_gait_file.hpp"
#include "motions/user_gait_program.hpp"
#include "modes/mode_sim.hpp"

namespace cerebellum {
namespace {

using testing::command;
using testing::ModeSim;

std::string read(const std::string& path) {
  std::ifstream in(path);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

struct Gait {
  UserGaitDefinition definition;
  UserGaitParameters parameters;
};

// a definition and human-form parameters, converted and parsed as the MC takes them
Gait load(const std::string& definition_text, const std::string& human_parameters) {
  Gait gait;
  const UserGaitParse definition = parse_user_gait_file(definition_text);
  EXPECT_TRUE(definition.file.has_value()) << definition.error;
  EXPECT_EQ(definition_problem(definition.file->definition), "");
  gait.definition = definition.file->definition;
  const UserGaitConversion converted = convert_gait_parameters(human_parameters);
  EXPECT_EQ(converted.error, "");
  const UserGaitParse parameters = parse_user_gait_file(converted.text);
  EXPECT_TRUE(parameters.file.has_value()) << parameters.error;
  EXPECT_EQ(parameters_problem(parameters.file->parameters), "");
  gait.parameters = parameters.file->parameters;
  return gait;
}

// a periodic pattern written out as a user gait: sections (contact, units) repeated, and one
// parameter step per cycle
struct Periodic {
  std::vector<std::pair<std::array<int, 4>, int>> cycle;
  int cycles = 8;
  double vx = 0.0;
  double x = 0.0;  // body_pos_des x of each step
  double lx = 0.0;
  double height = 0.05;
};

Gait periodic(const Periodic& p) {
  std::string definition = "# Gait Def\n";
  int cycle_units = 0;
  for (int c = 0; c < p.cycles; ++c) {
    for (const auto& [contact, units] : p.cycle) {
      definition += "[[section]]\ncontact = [" + std::to_string(contact[0]) + ", " + std::to_string(contact[1]) + ", " +
                    std::to_string(contact[2]) + ", " + std::to_string(contact[3]) +
                    "]\nduration = " + std::to_string(units) + "\n";
      if (c == 0) cycle_units += units;
    }
  }
  definition += "[[section]]\ncontact = [1, 1, 1, 1]\nduration = 4\n";
  std::string parameters = "# Gait Params\n";
  for (int c = 0; c < p.cycles; ++c) {
    const std::string lx = std::to_string(p.lx);
    const std::string h = std::to_string(p.height);
    parameters += "[[step]]\ntype = \"usergait\"\nbody_vel_des = [" + std::to_string(p.vx) +
                  ", 0.0, 0.0]\nbody_pos_des = [0.0, 0.0, 0.0, " + std::to_string(p.x) +
                  ", 0.0, 0.0]\nlanding_pos_des = [" + lx + ", 0, 0, " + lx + ", 0, 0, " + lx + ", 0, 0, " + lx +
                  ", 0, 0]\nstep_height = [" + h + ", " + h + ", " + h + ", " + h +
                  "]\nweight = [1, 1, 1, 1, 1, 1]\nuse_mpc_traj = 1\nmu = 0.4\nlanding_gain = 1.0\ngait_id = 110\n"
                  "duration = " +
                  std::to_string(cycle_units * 30) + "\n";
  }
  return load(definition, parameters);
}

// what the robot did while the gait ran
struct GaitRun {
  int sections_checked = 0;
  int contact_mismatches = 0;  // a stance foot in the air or a high-swing foot on the ground
  double lowest_height_m = 1.0;
  double largest_tilt_rad = 0.0;
  double progress_error = 0.0;                             // largest |bar - elapsed share|
  Eigen::Vector3d moved = Eigen::Vector3d::Zero();         // 1.5 s after the end
  Eigen::Vector3d moved_at_end = Eigen::Vector3d::Zero();  // when the gait's time is up
  bool ended_standing = false;
};

// check_swing: a foot in a swing section must be off the ground (gaits whose every swing is high)
GaitRun run_gait(const Gait& gait, bool check_swing) {
  ModeSim sim;
  sim.send(command(ModeId::RecoveryStand), 3.0);
  sim.send(command(ModeId::Locomotion, kStandGaitId), 1.0);
  const std::shared_ptr<const UserGaitProgram> program = build_user_gait_program(gait.definition, gait.parameters);
  sim.modes.user_gait_slot().publish(program);
  const Eigen::Vector3d start = sim.true_position();
  sim.send(command(ModeId::Locomotion, kUserGaitId), 0.0);
  const double t0 = sim.time_s();
  GaitRun run;
  double section_start = 0.0;
  for (const GaitSection& section : gait.definition.sections) {
    const double length = section.duration_units * kGaitSegmentS;
    // the middle of a section long enough for a foot to be clearly up or down
    const double middle = section_start + 0.5 * length;
    while (sim.time_s() - t0 < middle) {
      sim.run(0.002);
      run.lowest_height_m = std::min(run.lowest_height_m, sim.true_height());
      const Eigen::Vector3d rpy = sim.true_rpy();
      run.largest_tilt_rad = std::max({run.largest_tilt_rad, std::abs(rpy.x()), std::abs(rpy.y())});
      const double share = 100.0 * (sim.time_s() - t0) / program->duration_s();
      run.progress_error = std::max(run.progress_error, std::abs(sim.status().order_process_bar - share));
    }
    if (section.duration_units >= 3) {
      ++run.sections_checked;
      const GroundTruth truth = sim.backend.ground_truth();
      for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
        const bool stance = section.stance[leg];
        if (stance && !truth.foot_contact[leg]) ++run.contact_mismatches;
        if (!stance && check_swing && truth.foot_contact[leg]) ++run.contact_mismatches;
      }
    }
    section_start += length;
  }
  sim.run(program->duration_s() - (sim.time_s() - t0));
  run.moved_at_end = sim.true_position() - start;
  sim.run(1.5);
  run.moved = sim.true_position() - start;
  const Eigen::Vector3d rpy = sim.true_rpy();
  bool feet_down = true;
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) feet_down &= sim.true_foot(leg).z() < 0.03;
  std::printf(
      "user gait %.2f s: %d sections checked, %d contact mismatches, lowest %.3f m, tilt %.3f rad, "
      "bar error %.1f, moved %+.3f %+.3f m (%+.3f %+.3f at the end)\n",
      program->duration_s(), run.sections_checked, run.contact_mismatches, run.lowest_height_m, run.largest_tilt_rad,
      run.progress_error, run.moved.x(), run.moved.y(), run.moved_at_end.x(), run.moved_at_end.y());
  run.ended_standing = sim.status().mode == 11 && sim.status().gait_id == kUserGaitId &&
                       sim.status().order_process_bar == 100 && feet_down && std::abs(rpy.x()) < 0.05 &&
                       std::abs(rpy.y()) < 0.05 && std::abs(sim.true_height() - kDefaultBodyHeightM) < 0.02;
  return run;
}

TEST(UserGaitSim, TheShippedMoonwalkRunsOnItsContactPatternStaysUpAndEndsStanding) {
  const std::string folder = CEREBELLUM_SOURCE_DIR "/config/user_gaits/";
  const Gait gait = load(read(folder + "moonwalk_def.toml"), read(folder + "moonwalk_params.toml"));
  const GaitRun run = run_gait(gait, false);  // its sliding feet swing 1 cm high
  EXPECT_GT(run.sections_checked, 40);
  EXPECT_EQ(run.contact_mismatches, 0);
  EXPECT_GT(run.lowest_height_m, 0.17);
  EXPECT_LT(run.largest_tilt_rad, 0.25);
  EXPECT_LT(run.progress_error, 2.0);
  EXPECT_LT(run.moved.x(), -0.2);  // backwards, as its body velocity says
  EXPECT_TRUE(run.ended_standing);
}

TEST(UserGaitSim, AFourBeatWalkDefinedAsAUserGaitWalksForward) {
  Periodic walk;
  walk.cycle = {{{0, 1, 1, 1}, 5}, {{1, 1, 1, 1}, 2}, {{1, 1, 1, 0}, 5}, {{1, 1, 1, 1}, 2},
                {{1, 0, 1, 1}, 5}, {{1, 1, 1, 1}, 2}, {{1, 1, 0, 1}, 5}, {{1, 1, 1, 1}, 2}};
  walk.cycles = 6;
  walk.vx = 0.15;
  walk.lx = 0.04;
  const GaitRun run = run_gait(periodic(walk), true);
  EXPECT_EQ(run.contact_mismatches, 0);
  EXPECT_GT(run.lowest_height_m, 0.17);
  EXPECT_LT(run.largest_tilt_rad, 0.25);
  EXPECT_NEAR(run.moved.x(), 0.15 * 6 * 28 * 0.03, 0.3 * 0.15 * 6 * 28 * 0.03);
  EXPECT_TRUE(run.ended_standing);
}

TEST(UserGaitSim, ATwoBeatTrotDefinedAsAUserGaitTrotsAtItsVelocity) {
  Periodic trot;
  trot.cycle = {{{1, 0, 0, 1}, 6}, {{0, 1, 1, 0}, 6}};
  trot.cycles = 15;
  trot.vx = 0.3;
  trot.height = 0.06;
  const GaitRun run = run_gait(periodic(trot), true);
  EXPECT_EQ(run.contact_mismatches, 0);
  EXPECT_GT(run.lowest_height_m, 0.17);
  EXPECT_LT(run.largest_tilt_rad, 0.25);
  const double expected = 0.3 * 15 * 12 * 0.03;
  EXPECT_NEAR(run.moved.x(), expected, 0.15 * expected);
  EXPECT_TRUE(run.ended_standing);
}

// every foot down for 1.5 s and one step of 1.2 s without velocity: the body goes to body_pos_des x, y
Gait planted_step(double x, double y) {
  const std::string definition = "# Gait Def\n[[section]]\ncontact = [1, 1, 1, 1]\nduration = 50\n";
  const std::string parameters =
      "# Gait Params\n[[step]]\ntype = \"usergait\"\nbody_vel_des = [0.0, 0.0, 0.0]\nbody_pos_des = [0.0, 0.0, 0.0, " +
      std::to_string(x) + ", " + std::to_string(y) +
      ", 0.0]\nlanding_pos_des = [0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0]\nstep_height = [0.05, 0.05, 0.05, 0.05]\n"
      "weight = [1, 1, 1, 1, 1, 1]\nuse_mpc_traj = 1\nmu = 0.4\nlanding_gain = 1.0\ngait_id = 110\nduration = 1200\n";
  return load(definition, parameters);
}

// the firmware's "used when no velocity is given": 5 cm forward on planted feet, where the trunk
// is when the gait's time is up. It reaches 4.9 cm; without the decoding it ends 0.8 cm behind
// where it stood (a planted user stand drifts back slowly, as before), so 1 cm either way tells
// the two apart by more than four widths of the tolerance
TEST(UserGaitSim, AStepWithoutVelocityMovesTheTrunkToItsBodyPositionX) {
  const GaitRun run = run_gait(planted_step(0.05, 0.0), false);
  EXPECT_EQ(run.contact_mismatches, 0);
  EXPECT_NEAR(run.moved_at_end.x(), 0.05, 0.01);
  EXPECT_NEAR(run.moved_at_end.y(), 0.0, 0.01);
  EXPECT_TRUE(run.ended_standing);
}

// each step's body position counts from where that step begins: a trot with no velocity and 2 cm
// per cycle walks 15 x 2 cm (counted from the gait's start it would stop at 2 cm). Held to the
// 15 % the trot driven by velocity is
TEST(UserGaitSim, BodyPositionsOfStepsWithoutVelocityAddUpFromEachStepsStart) {
  Periodic trot;
  trot.cycle = {{{1, 0, 0, 1}, 6}, {{0, 1, 1, 0}, 6}};
  trot.cycles = 15;
  trot.x = 0.02;
  trot.height = 0.06;
  const GaitRun run = run_gait(periodic(trot), true);
  EXPECT_EQ(run.contact_mismatches, 0);
  EXPECT_LT(run.largest_tilt_rad, 0.25);
  EXPECT_NEAR(run.moved.x(), 15 * 0.02, 0.15 * 15 * 0.02);
  EXPECT_TRUE(run.ended_standing);
}

// a moonwalk in the seed's format (sections 2.2.1, 2.2.2) with other numbers than ours
struct Moonwalk {
  std::array<int, 8> n;  // N1..N8, units of 30 ms
  int cycles;
  double vx, lx, ly, h_max, h_min;
};

Gait moonwalk(const Moonwalk& m) {
  const std::array<std::array<int, 4>, 8> contacts{
      {{1, 1, 1, 1}, {0, 0, 0, 0}, {0, 1, 1, 0}, {0, 0, 0, 0}, {1, 1, 1, 1}, {0, 0, 0, 0}, {1, 0, 0, 1}, {0, 0, 0, 0}}};
  std::string definition = "# Gait Def\n";
  auto section = [&](const std::array<int, 4>& c, int n) {
    definition += "[[section]]\ncontact = [" + std::to_string(c[0]) + ", " + std::to_string(c[1]) + ", " +
                  std::to_string(c[2]) + ", " + std::to_string(c[3]) + "]\nduration = " + std::to_string(n) + "\n";
  };
  for (int c = 0; c < m.cycles; ++c) {
    for (std::size_t k = 0; k < 8; ++k) section(contacts[k], m.n[k]);
  }
  section({1, 1, 1, 1}, m.n[0]);
  const auto num = [](double v) { return std::to_string(v); };
  // per block: landing x of FR, FL, RR, RL (times lx), swing heights high on FR/RL first
  const std::array<std::array<double, 4>, 4> landing{{{1, 0, 0, 1}, {1, -1, -1, 1}, {0, 1, 1, 0}, {-1, 1, 1, -1}}};
  std::string parameters = "# Gait Params\n";
  for (int c = 0; c < m.cycles; ++c) {
    for (std::size_t b = 0; b < 4; ++b) {
      const bool fr_high = b < 2;
      std::string land;
      for (std::size_t leg = 0; leg < 4; ++leg) {
        land += (leg ? ", " : "") + num(landing[b][leg] * m.lx) + ", " + num(m.ly) + ", 0";
      }
      const double a = fr_high ? m.h_max : m.h_min;
      const double o = fr_high ? m.h_min : m.h_max;
      parameters += "[[step]]\ntype = \"usergait\"\nbody_vel_des = [" + num(m.vx) +
                    ", 0, 0]\nbody_pos_des = [0, 0, 0, 0, 0, 0]\nlanding_pos_des = [" + land + "]\nstep_height = [" +
                    num(a) + ", " + num(o) + ", " + num(o) + ", " + num(a) +
                    "]\nweight = [1, 1, 1, 1, 1, 1]\nuse_mpc_traj = 1\nmu = 0.5\nlanding_gain = 1.5\ngait_id = 110\n"
                    "duration = " +
                    std::to_string(30 * (m.n[2 * b] + m.n[2 * b + 1])) + "\n";
    }
  }
  return load(definition, parameters);
}

class MoonwalkVariant : public ::testing::TestWithParam<Moonwalk> {};

TEST_P(MoonwalkVariant, RunsOnItsContactPatternStaysUpAndEndsStanding) {
  const GaitRun run = run_gait(moonwalk(GetParam()), false);
  EXPECT_GT(run.sections_checked, 10);
  EXPECT_EQ(run.contact_mismatches, 0);
  EXPECT_GT(run.lowest_height_m, 0.17);
  EXPECT_LT(run.largest_tilt_rad, 0.3);
  EXPECT_TRUE(run.ended_standing);
}

// quicker and shorter; slower with longer strides and higher steps; feet landing 3 cm outwards;
// standing still (vx 0)
INSTANTIATE_TEST_SUITE_P(OtherNumbers, MoonwalkVariant,
                         ::testing::Values(Moonwalk{{3, 1, 4, 1, 3, 1, 4, 1}, 10, -0.08, 0.03, 0.0, 0.04, 0.005},
                                           Moonwalk{{6, 1, 8, 1, 6, 1, 8, 1}, 5, -0.04, 0.07, 0.0, 0.06, 0.015},
                                           Moonwalk{{4, 1, 6, 1, 4, 1, 6, 1}, 6, -0.06, 0.05, 0.03, 0.05, 0.01},
                                           Moonwalk{{4, 2, 5, 2, 4, 2, 5, 2}, 6, 0.0, 0.04, 0.0, 0.05, 0.01}));

TEST(UserGaitSim, WithoutAnUploadedGaitGait110IsRefused) {
  ModeSim sim;
  sim.send(command(ModeId::RecoveryStand), 3.0);
  sim.send(command(ModeId::Locomotion, kStandGaitId), 0.5);
  sim.send(command(ModeId::Locomotion, kUserGaitId), 0.2);
  EXPECT_EQ(sim.status().switch_status, SwitchStatus::BanTransition);
  EXPECT_EQ(sim.status().gait_id, kStandGaitId);
}

}  // namespace
}  // namespace cerebellum
