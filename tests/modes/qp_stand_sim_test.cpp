// Mode 3 and mode 11's stand gaits in simulation: the force-based stand reaches its pose targets,
// clamps out-of-range ones, balances on three legs with the fourth lifted, recovers from a push
// (gait 1) or only damps it (gait 31), and refuses walking gaits that are not registered.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "modes/mode_sim.hpp"

namespace cerebellum {
namespace {

using testing::command;
using testing::ModeSim;

HighLevelCommand qp_pose(double roll, double pitch, double yaw, double height) {
  HighLevelCommand c = command(ModeId::QpStand, 0);
  c.rpy_des = {static_cast<float>(roll), static_cast<float>(pitch), static_cast<float>(yaw)};
  c.pos_des = {0.0f, 0.0f, static_cast<float>(height)};
  return c;
}

// stands up (mode 12), then holds the QP stand at its default pose
void stand_in_qp_stand(ModeSim& sim) {
  sim.run(3.0);
  sim.send(command(ModeId::QpStand, 0), 1.5);
}

struct PoseCase {
  double roll, pitch, yaw, height;
};

TEST(QpStandSim, ReachesRollPitchYawAndHeightTargets) {
  for (const PoseCase& p :
       {PoseCase{0.3, 0.0, 0.0, 0.235}, PoseCase{0.0, 0.25, 0.0, 0.235}, PoseCase{0.0, -0.2, 0.0, 0.235},
        PoseCase{0.0, 0.0, 0.4, 0.235}, PoseCase{0.0, 0.0, 0.0, 0.2}, PoseCase{0.0, 0.0, 0.0, 0.28},
        PoseCase{0.15, 0.1, -0.2, 0.25}}) {
    ModeSim sim;
    stand_in_qp_stand(sim);
    const double yaw0 = sim.true_rpy().z();
    sim.send(qp_pose(p.roll, p.pitch, p.yaw, p.height), 0.1);
    EXPECT_EQ(sim.status().switch_status, SwitchStatus::Transitioning);
    sim.run(2.5);
    const Eigen::Vector3d rpy = sim.true_rpy();
    const std::string label = std::to_string(p.roll) + " " + std::to_string(p.pitch) + " " + std::to_string(p.yaw) +
                              " " + std::to_string(p.height);
    EXPECT_NEAR(rpy.x(), p.roll, 0.03) << label;
    EXPECT_NEAR(rpy.y(), -p.pitch, 0.03) << label << " (+pitch raises the head: a right-handed pitch of -pitch)";
    EXPECT_NEAR(wrap_angle(rpy.z() - yaw0), p.yaw, 0.03) << label;
    EXPECT_NEAR(sim.true_height(), p.height, 0.01) << label;
    EXPECT_EQ(sim.status().order_process_bar, 100) << label;
    EXPECT_EQ(sim.status().switch_status, SwitchStatus::Done) << label;
  }
}

TEST(QpStandSim, ClampsTargetsOutsideTheInterfaceRanges) {
  ModeSim sim;
  stand_in_qp_stand(sim);
  // height 0.05 -> 0.15; at 0.2 m (where the legs can reach it) roll 0.9 -> 0.52, pitch -0.6 -> -0.25
  // (0.25 head down: a right-handed pitch of +0.25)
  sim.send(qp_pose(0.0, 0.0, 0.0, 0.05), 2.5);
  EXPECT_NEAR(sim.true_height(), 0.15, 0.01);
  sim.send(qp_pose(0.9, 0.0, 0.0, 0.2), 3.0);
  EXPECT_NEAR(sim.true_rpy().x(), 0.52, 0.03);
  sim.send(qp_pose(0.0, -0.6, 0.0, 0.2), 3.0);
  EXPECT_NEAR(sim.true_rpy().y(), 0.25, 0.03);
  EXPECT_EQ(sim.status().mode, 3);
}

TEST(QpStandSim, GaitsOneAndThreeMoveThePoseFromWhereTheLastLeftItAndGaitZeroSetsIt) {
  ModeSim sim;
  stand_in_qp_stand(sim);
  const double yaw0 = sim.true_rpy().z();
  HighLevelCommand step = qp_pose(0.1, 0.0, 0.15, 0.0);
  step.gait_id = 1;
  sim.send(step, 2.5);
  step.gait_id = 3;
  sim.send(step, 2.5);
  EXPECT_NEAR(sim.true_rpy().x(), 0.2, 0.03) << "0.1 twice";
  EXPECT_NEAR(wrap_angle(sim.true_rpy().z() - yaw0), 0.3, 0.03);
  EXPECT_NEAR(sim.true_height(), 0.235, 0.01) << "height 0 in gaits 1, 3: unchanged";
  // the hold the queue puts after a timed entry adds nothing
  step = qp_pose(0.0, 0.1, 0.0, 0.0);
  step.gait_id = 1;
  step.duration = 500;
  sim.send(step, 3.0);
  EXPECT_EQ(sim.status().gait_id, 1);
  EXPECT_NEAR(sim.true_rpy().y(), -0.1, 0.03) << "head up 0.1, once";
  EXPECT_NEAR(sim.true_rpy().x(), 0.2, 0.03);
  // gait 0: absolute again
  sim.send(qp_pose(0.0, 0.0, 0.0, 0.25), 2.5);
  EXPECT_NEAR(sim.true_rpy().x(), 0.0, 0.03);
  EXPECT_NEAR(sim.true_rpy().y(), 0.0, 0.03);
  EXPECT_NEAR(sim.true_height(), 0.25, 0.01);
  EXPECT_EQ(sim.machine.counters().clamped.load(), 0u);
}

TEST(QpStandSim, BalancesOnThreeLegsWithEachLegLifted) {
  for (int leg = 0; leg < 4; ++leg) {
    ModeSim sim;
    stand_in_qp_stand(sim);
    HighLevelCommand lift = command(ModeId::QpStand, 0);
    lift.contact = 0x0F & ~(1 << leg);
    sim.send(lift, 0.5);
    EXPECT_EQ(sim.status().switch_status, SwitchStatus::Transitioning) << leg;
    sim.run(2.5);
    const auto l = static_cast<std::size_t>(leg);
    // the lifted foot 8 cm up, the others down, the body up and level
    EXPECT_GT(sim.true_foot(l).z() - robot::kFootRadius, 0.06) << leg;
    for (std::size_t other = 0; other < kNumLegs; ++other) {
      if (other != l) {
        EXPECT_LT(sim.true_foot(other).z() - robot::kFootRadius, 0.005) << leg << " " << other;
      }
    }
    EXPECT_NEAR(sim.true_height(), 0.235, 0.01) << leg;
    EXPECT_LT(std::abs(sim.true_rpy().x()), 0.03) << leg;
    EXPECT_LT(std::abs(sim.true_rpy().y()), 0.03) << leg;
    EXPECT_EQ(sim.status().order_process_bar, 100) << leg;
    EXPECT_EQ(sim.status().contact, 0x0F & ~(1 << leg)) << leg;
    // and put down again
    sim.send(command(ModeId::QpStand, 0), 3.0);
    EXPECT_LT(sim.true_foot(l).z() - robot::kFootRadius, 0.005) << leg;
    EXPECT_EQ(sim.status().contact, 0x0F) << leg;
    EXPECT_NEAR(sim.true_height(), 0.235, 0.01) << leg;
  }
}

TEST(QpStandSim, RefusesTwoLiftedLegs) {
  ModeSim sim;
  stand_in_qp_stand(sim);
  HighLevelCommand lift = command(ModeId::QpStand, 0);
  lift.contact = 0b1100;
  sim.send(lift, 0.1);
  EXPECT_EQ(sim.status().switch_status, SwitchStatus::BanTransition);
  EXPECT_EQ(sim.status().contact, 0x0F);
}

HighLevelCommand loco(int gait, double height = 0.0, double pitch = 0.0) {
  HighLevelCommand c = command(ModeId::Locomotion, gait);
  c.pos_des[2] = static_cast<float>(height);
  c.rpy_des[1] = static_cast<float>(pitch);
  return c;
}

TEST(LocomotionStandSim, FollowsHeightAndPitchWithinLocomotionRanges) {
  ModeSim sim;
  sim.run(3.0);
  sim.send(loco(1, 0.26, 0.1), 2.5);
  EXPECT_EQ(sim.status().mode, 11);
  EXPECT_EQ(sim.status().gait_id, 1);
  EXPECT_NEAR(sim.true_height(), 0.26, 0.01);
  EXPECT_NEAR(sim.true_rpy().y(), -0.1, 0.03) << "head up 0.1: a right-handed pitch of -0.1";
  // beyond the ranges: height 0.35 -> 0.28; pitch 0.5 -> 0.3 head up (one at a time)
  sim.send(loco(1, 0.35, 0.0), 2.5);
  EXPECT_NEAR(sim.true_height(), 0.28, 0.01);
  sim.send(loco(1, 0.0, 0.5), 2.5);
  EXPECT_NEAR(sim.true_rpy().y(), -0.3, 0.03);
}

TEST(LocomotionStandSim, VelocityChangesDoNotRestartTheStand) {
  ModeSim sim;
  sim.run(3.0);
  sim.send(loco(1), 2.0);
  ASSERT_EQ(sim.status().switch_status, SwitchStatus::Done);
  const Eigen::Vector3d foothold = sim.stand_gait.stand().controller().frame().foothold(0);
  HighLevelCommand walk = loco(1);
  walk.vel_des = {0.3f, 0.0f, 0.5f};
  sim.send(walk, 0.01);
  EXPECT_EQ(sim.status().switch_status, SwitchStatus::Done);
  sim.send(loco(31), 0.5);
  EXPECT_EQ(sim.status().gait_id, 31);
  EXPECT_EQ(sim.status().switch_status, SwitchStatus::Done);
  // the same stand kept running: its footholds were not re-anchored
  EXPECT_TRUE(sim.stand_gait.stand().controller().frame().foothold(0) == foothold);
}

TEST(LocomotionStandSim, AUserGaitWithNothingUploadedIsBannedWithAReason) {
  ModeSim sim;
  sim.run(3.0);
  sim.send(loco(1), 1.0);
  while (sim.machine.refusals().try_pop()) {
  }
  // the walking gaits are registered (the MC's mode set); the user gait has nothing to run
  sim.send(loco(110), 0.1);
  EXPECT_EQ(sim.status().mode, 11);
  EXPECT_EQ(sim.status().gait_id, 1);
  EXPECT_EQ(sim.status().switch_status, SwitchStatus::BanTransition);
  const auto note = sim.machine.refusals().try_pop();
  ASSERT_TRUE(note.has_value());
  EXPECT_STREQ(note->reason, "no user gait uploaded yet (user_gait_file: a definition and its parameters)");
}

// sideways offset of the trunk from the centre of its feet (simulator truth)
double offset_over_feet(const ModeSim& sim) {
  double feet_y = 0.0;
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) feet_y += sim.true_foot(leg).y() / kNumLegs;
  return sim.backend.ground_truth().position[1] - feet_y;
}

// pushed sideways while standing in a locomotion stand gait; returns the sideways offset over the
// feet 2 s later, relative to the one before the push
double offset_after_push(int gait) {
  ModeSim sim;
  sim.run(3.0);
  sim.send(loco(gait), 2.0);
  const double y0 = offset_over_feet(sim);
  sim.backend.set_external_force({0.0, 25.0, 0.0});
  sim.run(0.2);
  sim.backend.set_external_force({0.0, 0.0, 0.0});
  const double pushed = offset_over_feet(sim) - y0;
  EXPECT_GT(pushed, 0.005) << gait;
  sim.run(2.0);
  EXPECT_EQ(sim.status().mode, 11);
  EXPECT_NEAR(sim.true_height(), 0.235, 0.01) << gait;
  EXPECT_LT(std::abs(sim.true_rpy().x()), 0.03) << gait;
  return offset_over_feet(sim) - y0;
}

TEST(LocomotionStandSim, GaitOneReturnsOverItsFeetAfterAPushGaitThirtyOneStaysWhereItWasPushed) {
  const double with_recovery = offset_after_push(1);
  const double without_recovery = offset_after_push(31);
  EXPECT_LT(std::abs(with_recovery), 0.004);
  EXPECT_GT(without_recovery, 0.008);
}

}  // namespace
}  // namespace cerebellum
