// Picked up and set down in simulation: a hand (an external force on the trunk) lifts the
// standing robot; the machine reports LIFTED in mode 9 and resumes the stand once the robot is
// put back on its feet. Tipping over in a standing mode latches ori_error until a recovery stand.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>

#include "modes/mode_sim.hpp"

namespace cerebellum {
namespace {

using testing::command;
using testing::ModeSim;

constexpr double kWeightN = robot::kTotalMassKg * robot::kGravityMPerS2;

// a hand that holds the trunk at a height (spring and damper on the simulator's truth) and lets go
// once it has put the robot down below the height it is aiming for
struct Hand {
  void hold_at(ModeSim& sim, double height_m) {
    const GroundTruth t = sim.backend.ground_truth();
    const double force = kWeightN + 600.0 * (height_m - t.position[2]) - 60.0 * t.velocity_world[2];
    sim.backend.set_external_force({0.0, 0.0, std::max(force, 0.0)});
  }
  void release(ModeSim& sim) { sim.backend.set_external_force({0.0, 0.0, 0.0}); }
};

// stands in `stand`, is lifted 0.25 m by the hand, held, lowered onto its feet and let go
struct LiftRun {
  bool lifted_reported = false;  // mode 9 with switch_status LIFTED while in the air
  double lifted_after_s = -1.0;  // from the start of the pull
  int mode_after_landing = -1;
  int gait_after_landing = -1;
  double height_after_s = 0.0;  // trunk height 2 s after letting go
};

LiftRun lift_and_set_down(const HighLevelCommand& stand) {
  ModeSim sim;
  sim.run(3.0);
  sim.send(stand, 2.0);
  EXPECT_EQ(sim.status().mode, stand.mode);
  LiftRun run;
  Hand hand;
  const double start = sim.time_s();
  while (sim.time_s() < start + 2.5) {
    const double t = sim.time_s() - start;
    // up to 0.5 m, held, then lowered at 0.35 m/s until the feet carry the robot
    hand.hold_at(sim, t < 1.0 ? 0.5 : 0.5 - 0.35 * (t - 1.0));
    sim.run(0.002);
    if (sim.status().mode == 9 && sim.status().switch_status == SwitchStatus::Lifted && !run.lifted_reported) {
      run.lifted_reported = true;
      run.lifted_after_s = sim.time_s() - start;
    }
  }
  hand.release(sim);
  run.mode_after_landing = sim.status().mode;
  run.gait_after_landing = sim.status().gait_id;
  sim.run(2.0);
  run.height_after_s = sim.true_height();
  return run;
}

TEST(LiftedSim, QpStandIsLiftedAndResumesWhenSetDown) {
  const LiftRun run = lift_and_set_down(command(ModeId::QpStand, 0));
  EXPECT_TRUE(run.lifted_reported);
  EXPECT_GT(run.lifted_after_s, 0.0);
  EXPECT_LT(run.lifted_after_s, 0.5);
  EXPECT_EQ(run.mode_after_landing, 3);
  EXPECT_EQ(run.gait_after_landing, 1);
  EXPECT_NEAR(run.height_after_s, 0.235, 0.01);
}

TEST(LiftedSim, LocomotionStandResumesAsLocomotionStand) {
  const LiftRun run = lift_and_set_down(command(ModeId::Locomotion, 1));
  EXPECT_TRUE(run.lifted_reported);
  EXPECT_EQ(run.mode_after_landing, 11);
  EXPECT_EQ(run.gait_after_landing, 1);
  EXPECT_NEAR(run.height_after_s, 0.235, 0.01);
}

TEST(LiftedSim, PoseControlResumesAsQpStand) {
  const LiftRun run = lift_and_set_down(command(ModeId::PoseControl, 0));
  EXPECT_TRUE(run.lifted_reported);
  EXPECT_EQ(run.mode_after_landing, 3);
  EXPECT_NEAR(run.height_after_s, 0.235, 0.01);
}

TEST(LiftedSim, RecoveryStandIsNotWatched) {
  ModeSim sim;
  sim.run(3.0);
  Hand hand;
  const double start = sim.time_s();
  while (sim.time_s() < start + 1.0) {
    hand.hold_at(sim, 0.5);
    sim.run(0.002);
  }
  EXPECT_EQ(sim.status().mode, 12);
  EXPECT_GT(sim.true_height(), 0.4);
}

TEST(OrientationErrorSim, TippingOverStopsTheStandUntilARecoveryStand) {
  ModeSim sim;
  sim.run(3.0);
  sim.send(command(ModeId::PoseControl, 0), 1.0);
  // knocked onto its side
  const GroundTruth t = sim.backend.ground_truth();
  const Eigen::Quaterniond tipped(Eigen::AngleAxisd(1.4, Eigen::Vector3d::UnitX()));
  sim.backend.set_base_pose(t.position, {tipped.w(), tipped.x(), tipped.y(), tipped.z()});
  sim.run(0.01);
  EXPECT_EQ(sim.status().ori_error, 1);
  EXPECT_EQ(sim.status().switch_status, SwitchStatus::HighDamping);  // the seed: EDAMP, not ESTOP
  EXPECT_EQ(sim.status().mode, 7);
  sim.run(1.5);
  // a pose command is refused; only a recovery stand clears the error and stands the robot up
  sim.send(command(ModeId::PoseControl, 0), 0.1);
  EXPECT_EQ(sim.status().mode, 7);
  EXPECT_EQ(sim.status().ori_error, 1);
  sim.send(command(ModeId::RecoveryStand, 0), 0.1);
  EXPECT_EQ(sim.status().ori_error, 0);
  const double took =
      sim.run_until([&] { return sim.status().order_process_bar == 100 && sim.true_height() > 0.22; }, 12.0);
  EXPECT_GT(took, 0.0);
  EXPECT_EQ(sim.status().switch_status, SwitchStatus::Done);
}

}  // namespace
}  // namespace cerebellum
