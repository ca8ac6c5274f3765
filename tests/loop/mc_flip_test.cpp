// The flips (16/20 back, 16/21 front) through the whole MC in lockstep, judged on the simulation's
// ground truth: from the locomotion stand each plays its planned file, turns the trunk a full turn
// about its pitch axis (nose up for the back flip, nose down for the front flip) within the
// motors' limits and lands standing near its take-off (docs/jumps.md, "Flips").
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <ostream>
#include <stdexcept>
#include <string>

#include "backend/sim_fixture.hpp"
#include "loop/lockstep_client.hpp"
#include "mc_fixture.hpp"
#include "loop/simulated_robot.hpp"
#include "modes/jump_mode.hpp"

namespace cerebellum {
namespace {

struct FlipCase {
  int gait_id;
  double turn_sign;  // the SDK's pitch sign: nose up (a back flip) is negative
  const char* name;
};

void PrintTo(const FlipCase& flip, std::ostream* out) { *out << flip.name << " flip (16/" << flip.gait_id << ")"; }

class McFlips : public ::testing::TestWithParam<FlipCase> {};

TEST_P(McFlips, AFlipFromAStandTurnsAFullTurnWithinTheMotorsLimitsAndStandsNearItsTakeOff) {
  const FlipCase flip = GetParam();
  Mc mc = make_simulated_mc(testing::lying_start());
  LockstepClient client(mc);
  client.run(high_level_command(ModeId::RecoveryStand, 0), 3.0);
  client.run(high_level_command(ModeId::Locomotion, 1), 1.0);
  const GroundTruth before = mc.simulation().ground_truth();
  double turned_rad = 0.0;
  double peak_torque_nm = 0.0;
  bool damped = false;
  int last_bar = 0;
  bool progress_never_fell = true;
  client.run(high_level_command(ModeId::Jump3d, flip.gait_id), 5.0, [&](const CycleRecord&) {
    const GroundTruth g = mc.simulation().ground_truth();
    turned_rad += g.angular_velocity_body[1] * mc.config().loop_period_s;
    for (double tau : g.tau) peak_torque_nm = std::max(peak_torque_nm, std::abs(tau));
    const HighLevelStatus& s = mc.machine().status();
    damped |= s.mode == static_cast<int>(ModeId::PureDamper);
    if (s.mode == static_cast<int>(ModeId::Jump3d)) {
      progress_never_fell &= s.order_process_bar >= last_bar;
      last_bar = s.order_process_bar;
    }
  });
  const GroundTruth after = mc.simulation().ground_truth();
  const HighLevelStatus& status = mc.machine().status();
  EXPECT_GT(flip.turn_sign * turned_rad, 2.0 * robot::kPi - 0.3);
  EXPECT_LE(peak_torque_nm, robot::kTorqueMaxNm + 1e-9);
  EXPECT_FALSE(damped);
  EXPECT_LT(std::hypot(after.position[0] - before.position[0], after.position[1] - before.position[1]), 0.5);
  const Eigen::Vector3d rpy = testing::truth_rpy(after);
  EXPECT_LT(std::max(std::abs(rpy.x()), std::abs(rpy.y())), 0.1);
  EXPECT_GT(after.position[2], 0.2);
  EXPECT_EQ(status.mode, static_cast<int>(ModeId::Jump3d));
  EXPECT_EQ(status.gait_id, flip.gait_id);
  EXPECT_EQ(status.order_process_bar, 100);
  EXPECT_TRUE(progress_never_fell);
}

TEST_P(McFlips, WithoutItsFlipFileTheFlipIsRefusedAndTheRobotStandsOn) {
  const FlipCase flip = GetParam();
  McConfig config = testing::lying_start();
  (flip.gait_id == kBackFlipGaitId ? config.back_flip_path : config.front_flip_path) = "";
  Mc mc = make_simulated_mc(config);
  LockstepClient client(mc);
  client.run(high_level_command(ModeId::RecoveryStand, 0), 3.0);
  client.run(high_level_command(ModeId::Locomotion, 1), 1.0);
  client.run(high_level_command(ModeId::Jump3d, flip.gait_id), 0.3);
  EXPECT_EQ(mc.machine().status().switch_status, SwitchStatus::BanTransition);
  EXPECT_EQ(mc.machine().status().mode, static_cast<int>(ModeId::Locomotion));
  EXPECT_GT(mc.simulation().ground_truth().position[2], 0.2);
}

INSTANTIATE_TEST_SUITE_P(BothFlips, McFlips,
                         ::testing::Values(FlipCase{kBackFlipGaitId, -1.0, "back"}, FlipCase{kFrontFlipGaitId, 1.0, "front"}),
                         [](const ::testing::TestParamInfo<FlipCase>& info) { return std::string(info.param.name); });

TEST(McFlipFiles, AMalformedFlipFileStopsTheStartWithItsLineAndReason) {
  const std::string path = ::testing::TempDir() + "/bad_flip.csv";
  std::ofstream(path) << "# a flip\ntime_s,phase\n0,0\n";
  for (const char* flip : {"back flip", "front flip"}) {
    McConfig config = default_config();
    (std::string(flip) == "back flip" ? config.back_flip_path : config.front_flip_path) = path;
    try {
      Mc mc = make_simulated_mc(config);
      ADD_FAILURE() << "the MC started with a malformed " << flip << " file";
    } catch (const std::invalid_argument& error) {
      EXPECT_EQ(std::string(error.what()).rfind(std::string(flip) + ": " + path + ": line 2: the header is not", 0), 0u)
          << error.what();
    }
  }
}

}  // namespace
}  // namespace cerebellum
