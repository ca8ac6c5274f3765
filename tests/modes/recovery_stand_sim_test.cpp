// Mode 12 in simulation: from lying, from either side and from the back the robot ends up
// standing within a time budget.
#include <gtest/gtest.h>

#include <cmath>

#include "modes/mode_sim.hpp"

namespace cerebellum {
namespace {

using testing::command;
using testing::ModeSim;

// standing: high, level, done
bool standing(const ModeSim& sim) {
  const Eigen::Vector3d rpy = sim.true_rpy();
  return sim.status().mode == 12 && sim.status().order_process_bar == 100 && sim.true_height() > 0.22 &&
         std::abs(rpy.x()) < 0.1 && std::abs(rpy.y()) < 0.1;
}

// the robot dropped in this orientation with its motors off, left to settle, then told to stand
double time_to_stand_from(const Eigen::Quaterniond& orientation, int gait, ModeSim& sim) {
  sim.backend.set_base_pose({0.0, 0.0, 0.3}, {orientation.w(), orientation.x(), orientation.y(), orientation.z()});
  sim.run(1.5);
  sim.send(command(ModeId::RecoveryStand, gait), 0.0);
  return sim.run_until([&] { return standing(sim); }, 15.0);
}

Eigen::Quaterniond rolled(double roll) { return Eigen::Quaterniond(Eigen::AngleAxisd(roll, Eigen::Vector3d::UnitX())); }

TEST(RecoveryStandSim, StandsUpFromLyingOnTheBellyWithoutRolling) {
  ModeSim sim(ModeId::Off);
  const double t = time_to_stand_from(Eigen::Quaterniond::Identity(), 0, sim);
  EXPECT_GT(t, 0.0);
  EXPECT_LT(t, 3.0);
  EXPECT_EQ(sim.recovery_stand.roll_attempts(), 0);
}

TEST(RecoveryStandSim, RightsItselfFromItsRightSide) {
  ModeSim sim(ModeId::Off);
  const double t = time_to_stand_from(rolled(1.5708), 0, sim);
  EXPECT_GT(t, 0.0);
  EXPECT_LT(t, 10.0);
  EXPECT_GE(sim.recovery_stand.roll_attempts(), 1);
}

TEST(RecoveryStandSim, RightsItselfFromItsLeftSide) {
  ModeSim sim(ModeId::Off);
  const double t = time_to_stand_from(rolled(-1.5708), 0, sim);
  EXPECT_GT(t, 0.0);
  EXPECT_LT(t, 10.0);
  EXPECT_GE(sim.recovery_stand.roll_attempts(), 1);
}

TEST(RecoveryStandSim, RightsItselfFromItsBackOverEitherFlank) {
  for (int gait : {0, RecoveryStandMode::kRollOverLeft, RecoveryStandMode::kRollOverRight}) {
    ModeSim sim(ModeId::Off);
    const double t = time_to_stand_from(rolled(3.1416), gait, sim);
    EXPECT_GT(t, 0.0) << gait;
    EXPECT_LT(t, 10.0) << gait;
    EXPECT_EQ(sim.recovery_stand.roll_attempts(), 1) << gait;
    EXPECT_EQ(sim.status().gait_id, gait);
  }
}

TEST(RecoveryStandSim, RollsAgainWhenKnockedOntoItsSideWhileRising) {
  ModeSim sim(ModeId::Off);
  sim.run(1.0);
  sim.send(command(ModeId::RecoveryStand, 0), 0.5);
  ASSERT_EQ(sim.recovery_stand.roll_attempts(), 0);
  // a hard sideways shove while the legs unfold: the body goes over onto its side
  sim.backend.set_external_force({0.0, 150.0, 0.0});
  sim.run_until([&] { return std::abs(sim.true_rpy().x()) > 1.2; }, 1.5);
  sim.backend.set_external_force({0.0, 0.0, 0.0});
  ASSERT_GT(std::abs(sim.true_rpy().x()), 1.2);
  EXPECT_GT(sim.run_until([&] { return standing(sim); }, 15.0), 0.0);
  EXPECT_GE(sim.recovery_stand.roll_attempts(), 1);
}

TEST(RecoveryStandSim, ProgressRunsThroughTheRollAndTheStand) {
  ModeSim sim(ModeId::Off);
  sim.backend.set_base_pose({0.0, 0.0, 0.3}, {0.0, 1.0, 0.0, 0.0});
  sim.run(1.5);
  sim.send(command(ModeId::RecoveryStand, 0), 0.5);
  EXPECT_LT(sim.status().order_process_bar, 50);
  EXPECT_EQ(sim.status().switch_status, SwitchStatus::Transitioning);
  ASSERT_GT(sim.run_until([&] { return standing(sim); }, 15.0), 0.0);
  EXPECT_EQ(sim.status().switch_status, SwitchStatus::Done);
}

}  // namespace
}  // namespace cerebellum
