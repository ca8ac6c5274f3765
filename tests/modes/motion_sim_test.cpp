// Mode 62 in simulation: every shipped motion runs to its end through the modes it is made of,
// reported as mode 62 with the motion's id and a progress bar that climbs to 100, without a fall,
// and leaves the robot standing where and how it stood before (a level stand at the height it
// started from, centred over its feet). Judged on the simulator's truth.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "modes/mode_sim.hpp"

namespace cerebellum {
namespace {

using testing::command;
using testing::ModeSim;

HighLevelCommand motion(int id, int duration_ms = 0) {
  HighLevelCommand c = command(ModeId::Motion, id);
  c.duration = duration_ms;  // the seed's example sends 0
  return c;
}

struct StandPose {
  Eigen::Vector3d position;
  Eigen::Vector3d rpy;
};

StandPose true_pose(const ModeSim& sim) {
  const GroundTruth truth = sim.backend.ground_truth();
  return {Eigen::Vector3d(truth.position[0], truth.position[1], truth.position[2]), sim.true_rpy()};
}

// what a motion did, seen from outside
struct MotionRun {
  double reported_s = -1.0;  // from the command until the response showed 100 again
  double lowest_height_m = 1.0;
  double largest_tilt_rad = 0.0;
  double highest_foot_m = 0.0;  // the highest any foot rose above its stand height
  int lowest_progress_seen = 100;
  bool progress_went_back = false;
  bool always_reported_62 = true;
};

MotionRun run_motion(ModeSim& sim, int id, double max_s) {
  MotionRun run;
  std::array<double, kNumLegs> foot_stand{};
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) foot_stand[leg] = sim.true_foot(leg).z();
  sim.send(motion(id), 0.002);
  int last_progress = 0;
  const double start = sim.time_s();
  run.reported_s = sim.run_until(
      [&] {
        const HighLevelStatus& s = sim.status();
        run.always_reported_62 = run.always_reported_62 && s.mode == 62 && s.gait_id == id;
        run.lowest_progress_seen = std::min(run.lowest_progress_seen, s.order_process_bar);
        run.progress_went_back = run.progress_went_back || s.order_process_bar < last_progress;
        last_progress = s.order_process_bar;
        run.lowest_height_m = std::min(run.lowest_height_m, sim.true_height());
        const Eigen::Vector3d rpy = sim.true_rpy();
        run.largest_tilt_rad = std::max({run.largest_tilt_rad, std::abs(rpy.x()), std::abs(rpy.y())});
        for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
          run.highest_foot_m = std::max(run.highest_foot_m, sim.true_foot(leg).z() - foot_stand[leg]);
        }
        return s.order_process_bar == 100;
      },
      max_s);
  if (run.reported_s >= 0.0) run.reported_s = sim.time_s() - start;
  return run;
}

struct MotionCase {
  int id;
  double minimum_s;      // the reference's minimum duration
  double foot_rise_m;    // at least one foot rises this high above its stand height (0: none needs to)
  bool travels = false;  // walks away from where it started (the moonwalk)
};

class EveryMotion : public ::testing::TestWithParam<MotionCase> {};

TEST_P(EveryMotion, RunsToItsEndWithoutAFallAndLeavesTheRobotInItsStandPose) {
  const MotionCase c = GetParam();
  ModeSim sim;
  sim.send(command(ModeId::RecoveryStand), 3.0);
  sim.send(command(ModeId::PoseControl, 0), 1.5);  // the stand pose: level, centre of mass over the feet
  const StandPose before = true_pose(sim);
  const Motion* planned = sim.modes.motion().library().find(c.id);
  ASSERT_NE(planned, nullptr);

  const MotionRun run = run_motion(sim, c.id, 60.0);
  ASSERT_GE(run.reported_s, 0.0) << "motion " << c.id << " never reported 100";
  EXPECT_TRUE(run.always_reported_62);
  EXPECT_FALSE(run.progress_went_back);
  EXPECT_EQ(run.lowest_progress_seen, 0);
  // as long as its steps (and the return to the stand), at least the reference's minimum
  EXPECT_GE(run.reported_s, c.minimum_s);
  EXPECT_NEAR(run.reported_s, planned->duration_s() + MotionModeConfig{}.final_stand_ms * 1e-3, 0.1);
  EXPECT_GT(run.lowest_height_m, 0.14);
  EXPECT_LT(run.largest_tilt_rad, 0.6);
  EXPECT_GE(run.highest_foot_m, c.foot_rise_m);

  // the entry ends, the queue holds the pose (21/3); the robot stands as before
  sim.run(1.0);
  EXPECT_EQ(sim.status().mode, 21);
  EXPECT_EQ(sim.status().gait_id, 3);
  const StandPose after = true_pose(sim);
  const Eigen::Vector3d moved = after.position - before.position;
  if (c.travels) {
    EXPECT_GT(moved.head<2>().norm(), 0.1);
    EXPECT_NEAR(moved.z(), 0.0, 0.01);
  } else {
    EXPECT_LT(moved.norm(), 0.01) << "moved by " << moved.transpose();
  }
  EXPECT_NEAR(after.rpy.x(), before.rpy.x(), 0.05);
  EXPECT_NEAR(after.rpy.y(), before.rpy.y(), 0.05);
  EXPECT_NEAR(wrap_angle(after.rpy.z() - before.rpy.z()), 0.0, 0.05);
}

INSTANTIATE_TEST_SUITE_P(ShippedMotions, EveryMotion,
                         ::testing::Values(MotionCase{1, 8.6, 0.08}, MotionCase{2, 8.6, 0.08}, MotionCase{3, 1.3, 0.0},
                                           MotionCase{4, 3.9, 0.0}, MotionCase{5, 3.9, 0.0}, MotionCase{6, 3.3, 0.0},
                                           MotionCase{11, 27.0, 0.08}, MotionCase{12, 9.0, 0.04, true},
                                           MotionCase{34, 14.0, 0.0}),
                         [](const ::testing::TestParamInfo<MotionCase>& info) {
                           return "Motion" + std::to_string(info.param.id);
                         });

TEST(MotionSim, AMotionCommandWhileAMotionRunsIsDroppedAndCounted) {
  ModeSim sim;
  sim.send(command(ModeId::RecoveryStand), 3.0);
  sim.send(motion(2), 1.0);
  ASSERT_EQ(sim.status().mode, 62);
  sim.send(motion(3), 1.0);
  EXPECT_EQ(sim.status().gait_id, 2);
  EXPECT_EQ(sim.machine.counters().motions_dropped.load(), 1u);
  // the dropped one does not run after the first either
  sim.run_until([&] { return sim.status().order_process_bar == 100; }, 20.0);
  sim.run(2.0);
  EXPECT_EQ(sim.status().mode, 21);
  EXPECT_EQ(sim.status().gait_id, 3);
}

TEST(MotionSim, AMotionWithALongerDurationStandsUntilItsDurationEnds) {
  ModeSim sim;
  sim.send(command(ModeId::RecoveryStand), 3.0);
  const double planned_s =
      sim.modes.motion().library().find(3)->duration_s() + MotionModeConfig{}.final_stand_ms * 1e-3;
  sim.send(motion(3, 5000), 0.002);
  const double start = sim.time_s() - 0.002;
  const double ended = sim.run_until([&] { return sim.status().mode != 62; }, 10.0);
  ASSERT_GE(ended, 0.0);
  EXPECT_GT(planned_s, 1.5);
  EXPECT_NEAR(sim.time_s() - start, 5.0, 0.01);
}

TEST(MotionSim, AMotionAfterARecoveryStandEndsLevelAtTheHeightItStartedFrom) {
  ModeSim sim;
  sim.send(command(ModeId::RecoveryStand), 3.0);  // the seed's flow: 12, then 62/2
  const double height_before = sim.true_height();
  ASSERT_GT(std::abs(height_before - kDefaultBodyHeightM), 0.01);  // not the default height
  ASSERT_GE(run_motion(sim, 2, 20.0).reported_s, 0.0);
  sim.run(1.0);
  EXPECT_NEAR(sim.true_height(), height_before, 0.01);
  EXPECT_LT(std::abs(sim.true_rpy().x()), 0.05);
  EXPECT_LT(std::abs(sim.true_rpy().y()), 0.05);
}

TEST(MotionSim, ARecoveryStandInterruptsAHandShakeAndTheRobotEndsStanding) {
  ModeSim sim;
  sim.send(command(ModeId::RecoveryStand), 3.0);
  const double stand_height = sim.true_height();
  sim.send(motion(1), 3.5);  // the front left foot is up
  ASSERT_GT(sim.true_foot(1).z(), 0.06);
  sim.send(command(ModeId::RecoveryStand), 4.0);
  EXPECT_EQ(sim.status().mode, 12);
  EXPECT_EQ(sim.status().order_process_bar, 100);
  EXPECT_NEAR(sim.true_height(), stand_height, 0.02);
  EXPECT_LT(std::abs(sim.true_rpy().x()) + std::abs(sim.true_rpy().y()), 0.05);
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) EXPECT_LT(sim.true_foot(leg).z(), 0.03) << "leg " << leg;
}

TEST(MotionSim, AClientThatVanishesMidHandShakeLeavesTheRobotDampedAndUpright) {
  ModeSim sim;
  sim.send(command(ModeId::RecoveryStand), 3.0);
  sim.send(motion(2), 3.5);  // the front right foot is up
  ASSERT_GT(sim.true_foot(0).z(), 0.06);
  // the loop runs on, nobody sends: after 0.5 s the MC damps the joints (get-down protection)
  for (int i = 0; i < 2000; ++i) sim.loop.tick();
  EXPECT_EQ(sim.status().mode, 7);
  EXPECT_EQ(sim.machine.counters(HighLevelSource::CyberDog2Lcm).timeouts.load(), 1u);
  // down on its belly, not on its side or back
  EXPECT_LT(std::abs(sim.true_rpy().x()), 0.5);
  EXPECT_LT(std::abs(sim.true_rpy().y()), 0.5);
  EXPECT_LT(sim.true_height(), 0.15);
}

TEST(MotionSim, AMotionFromOffStandsUpFirst) {
  ModeSim sim(ModeId::Off);
  sim.run(1.0);
  ASSERT_LT(sim.true_height(), 0.15);
  sim.send(motion(3), 0.1);
  EXPECT_EQ(sim.status().mode, 62);
  EXPECT_EQ(sim.status().order_process_bar, 0);
  const double ended = sim.run_until([&] { return sim.status().order_process_bar == 100; }, 15.0);
  ASSERT_GE(ended, 0.0);
  EXPECT_NEAR(sim.true_height(), kDefaultBodyHeightM, 0.015);
}

TEST(MotionSim, AnUnknownMotionIdIsRefusedAndTheStandGoesOn) {
  ModeSim sim;
  sim.send(command(ModeId::RecoveryStand), 3.0);
  sim.send(motion(57), 0.5);
  EXPECT_EQ(sim.status().switch_status, SwitchStatus::BanTransition);
  EXPECT_EQ(sim.status().mode, 12);
}

}  // namespace
}  // namespace cerebellum
