// Mode 21 in simulation: position-based pose control reaches its poses (gait 0, incremental: each
// command moves the body from where the last one left it; +pitch raises the head) and heights
// (gait 5), rotates about the control point, lifts a leg for a hand shake (gait 2) while the body
// stays up, holds wherever it is told to (gait 3), and clamps out-of-range commands, saying so.
#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <string>

#include "modes/mode_sim.hpp"

namespace cerebellum {
namespace {

using testing::command;
using testing::ModeSim;

HighLevelCommand pose(double roll, double pitch, double yaw, double dz = 0.0) {
  HighLevelCommand c = command(ModeId::PoseControl, 0);
  c.rpy_des = {static_cast<float>(roll), static_cast<float>(pitch), static_cast<float>(yaw)};
  c.pos_des = {0.0f, 0.0f, static_cast<float>(dz)};
  return c;
}

HighLevelCommand height(double height_m, int duration_ms) {
  HighLevelCommand c = command(ModeId::PoseControl, 5);
  c.pos_des = {0.0f, 0.0f, static_cast<float>(height_m)};
  c.duration = duration_ms;
  return c;
}

// stands up (mode 12), then takes over in pose control at the stand pose (height 0.235)
void stand_in_pose_control(ModeSim& sim) {
  sim.run(3.0);
  sim.send(pose(0, 0, 0), 1.0);
}

struct PoseCase {
  double roll, pitch, yaw, dz;
};

TEST(PoseControlSim, ReachesCommandedRollPitchYawAndHeightOffset) {
  for (const PoseCase& p :
       {PoseCase{0.3, 0.0, 0.0, 0.0}, PoseCase{0.0, 0.3, 0.0, 0.0}, PoseCase{0.0, -0.3, 0.0, 0.0},
        PoseCase{0.0, 0.0, -0.4, 0.0}, PoseCase{0.0, 0.0, 0.0, -0.05}, PoseCase{0.15, -0.1, 0.2, 0.02}}) {
    ModeSim sim;
    stand_in_pose_control(sim);
    const double yaw0 = sim.true_rpy().z();
    sim.send(pose(p.roll, p.pitch, p.yaw, p.dz), 0.1);
    EXPECT_EQ(sim.status().switch_status, SwitchStatus::Transitioning);
    sim.run(2.0);
    const Eigen::Vector3d rpy = sim.true_rpy();
    const std::string label = std::to_string(p.roll) + " " + std::to_string(p.pitch) + " " + std::to_string(p.yaw);
    EXPECT_NEAR(rpy.x(), p.roll, 0.03) << label;
    EXPECT_NEAR(rpy.y(), -p.pitch, 0.03) << label << " (+pitch raises the head: a right-handed pitch of -pitch)";
    EXPECT_NEAR(wrap_angle(rpy.z() - yaw0), p.yaw, 0.03) << label;
    // pitch about the body origin leaves its height alone
    EXPECT_NEAR(sim.true_height(), 0.235 + p.dz, 0.01) << label;
    EXPECT_EQ(sim.status().switch_status, SwitchStatus::Done) << label;
  }
}

TEST(PoseControlSim, GaitFiveSetsTheAbsoluteHeightAndNeedsADuration) {
  ModeSim sim;
  stand_in_pose_control(sim);
  sim.send(height(0.2, 1000), 0.9);
  EXPECT_EQ(sim.status().gait_id, 5);
  EXPECT_EQ(sim.status().order_process_bar, 100);  // a timed entry's clock runs while it moves
  sim.run(1.0);
  EXPECT_NEAR(sim.true_height(), 0.2, 0.01);
  // after the timed entry the queue holds the pose: (21, 3)
  EXPECT_EQ(sim.status().gait_id, 3);
  EXPECT_NEAR(sim.true_height(), 0.2, 0.01);
  sim.send(height(0.26, 1000), 2.0);
  EXPECT_NEAR(sim.true_height(), 0.26, 0.01);
  // beyond the range: 0.35 -> 0.27, 0.05 -> 0.15
  sim.send(height(0.35, 1000), 2.0);
  EXPECT_NEAR(sim.true_height(), 0.27, 0.01);
  sim.send(height(0.05, 1500), 2.5);
  EXPECT_NEAR(sim.true_height(), 0.15, 0.01);
  // duration 0 is refused
  sim.send(height(0.22, 0), 0.1);
  EXPECT_EQ(sim.status().switch_status, SwitchStatus::BanTransition);
}

TEST(PoseControlSim, ClampsRollPitchYawToTheirRanges) {
  for (int axis = 0; axis < 3; ++axis) {
    ModeSim sim;
    stand_in_pose_control(sim);
    sim.send(height(0.2, 500), 1.0);
    const double yaw0 = sim.true_rpy().z();
    HighLevelCommand c = pose(0.0, 0.0, 0.0);
    c.rpy_des[static_cast<std::size_t>(axis)] = -1.0f;
    sim.send(c, 2.5);
    Eigen::Vector3d rpy = sim.true_rpy();
    rpy.z() = wrap_angle(rpy.z() - yaw0);
    // -1 head down is 0.45 head down: a right-handed pitch of +0.45
    EXPECT_NEAR(rpy[axis], axis == 1 ? 0.45 : -0.45, 0.03) << axis;
    // taken, and the client told so
    EXPECT_EQ(sim.machine.counters().clamped.load(), 1u) << axis;
    std::optional<ClientNote> note = sim.machine.refusals().try_pop();
    ASSERT_TRUE(note.has_value()) << axis;
    EXPECT_TRUE(note->clamped);
    EXPECT_EQ(sim.status().switch_status, SwitchStatus::Done) << axis;
  }
}

TEST(PoseControlSim, HeadUpThenHeadDownEndsLevelAsTheSeedsBasicMotionExampleExpects) {
  // the seed's section 2.4.1: 21/0 rpy_des [0, 0.3, 0] "Head up" for 0.5 s, then [0, -0.3, 0]
  // "Head down" for 0.3 s: incremental, so the second undoes the first
  ModeSim sim;
  stand_in_pose_control(sim);
  const double pitch0 = sim.true_rpy().y();
  HighLevelCommand up = pose(0.0, 0.3, 0.0);
  up.duration = 500;
  sim.send(up, 0.5);
  sim.run(0.2);
  EXPECT_NEAR(sim.true_rpy().y() - pitch0, -0.3, 0.03) << "the nose is up";
  HighLevelCommand down = pose(0.0, -0.3, 0.0);
  down.duration = 300;
  sim.send(down, 0.3);
  sim.run(0.3);
  EXPECT_NEAR(sim.true_rpy().y(), 0.0, 0.03) << "level again";
  EXPECT_EQ(sim.machine.counters().clamped.load(), 0u);
}

TEST(PoseControlSim, EachPoseCommandMovesTheBodyFromWhereTheLastLeftIt) {
  ModeSim sim;
  stand_in_pose_control(sim);
  const double yaw0 = sim.true_rpy().z();
  sim.send(pose(0.1, 0.0, 0.15), 1.5);
  sim.send(pose(0.1, 0.0, 0.15), 1.5);
  Eigen::Vector3d rpy = sim.true_rpy();
  EXPECT_NEAR(rpy.x(), 0.2, 0.03);
  EXPECT_NEAR(wrap_angle(rpy.z() - yaw0), 0.3, 0.03);
  // heartbeats (the same life_count) move nothing: ModeSim repeats the last command every 0.1 s
  sim.run(1.0);
  EXPECT_NEAR(sim.true_rpy().x(), 0.2, 0.03);
  // a hold, then a height (gait 5: absolute, level), then an increment from there
  sim.send(command(ModeId::PoseControl, 3), 0.5);
  sim.send(height(0.2, 500), 1.5);
  EXPECT_NEAR(sim.true_rpy().x(), 0.0, 0.03);
  EXPECT_NEAR(sim.true_height(), 0.2, 0.01);
  sim.send(pose(0.0, 0.0, 0.0, 0.03), 1.5);
  EXPECT_NEAR(sim.true_height(), 0.23, 0.01);
}

TEST(PoseControlSim, PosesBeyondTheLegsReachAreCutBackAndHeldSafely) {
  ModeSim sim;
  stand_in_pose_control(sim);
  // pitch (head down) and yaw at their limits together, at the stand height: the rear legs cannot
  // reach
  sim.send(pose(0.0, -0.45, 0.45), 2.5);
  const Eigen::Vector3d rpy = sim.true_rpy();
  EXPECT_GT(rpy.y(), 0.1);
  EXPECT_LT(rpy.y(), 0.45);
  EXPECT_GT(sim.true_height(), 0.2);
  EXPECT_EQ(sim.status().switch_status, SwitchStatus::Done);
  for (std::size_t i = 0; i < kNumJoints; ++i) {
    const robot::JointRange range = robot::joint_range(i);
    EXPECT_GT(sim.state().q[i], range.lower + 0.02) << i;
    EXPECT_LT(sim.state().q[i], range.upper - 0.02) << i;
  }
}

TEST(PoseControlSim, PitchTurnsAboutTheControlPoint) {
  ModeSim sim;
  stand_in_pose_control(sim);
  const Eigen::Vector3d point_in_body(0.2, 0.0, 0.0);
  const auto point_in_world = [&] {
    const GroundTruth t = sim.backend.ground_truth();
    return Eigen::Vector3d(Eigen::Vector3d(t.position[0], t.position[1], t.position[2]) +
                           sim.true_orientation() * point_in_body);
  };
  sim.send(height(0.2, 500), 1.0);
  const Eigen::Vector3d before = point_in_world();
  HighLevelCommand c = pose(0.0, -0.2, 0.0);  // head down 0.2
  c.ctrl_point = {0.2f, 0.0f, 0.0f};
  sim.send(c, 2.0);
  EXPECT_NEAR(sim.true_rpy().y(), 0.2, 0.03);
  // the head point stays put (a pitch about the body origin would drop it by 4 cm)
  EXPECT_LT((point_in_world() - before).norm(), 0.01);
}

TEST(PoseControlSim, HandShakeLiftsTheRightFrontFootWhileTheBodyStaysUp) {
  ModeSim sim;
  stand_in_pose_control(sim);
  HighLevelCommand shake = command(ModeId::PoseControl, 2);
  shake.contact = 0b1110;
  shake.foot_pose = {0.08f, 0.0f, 0.12f, 0.0f, 0.0f, 0.0f};
  sim.send(shake, 0.5);
  EXPECT_EQ(sim.status().switch_status, SwitchStatus::Transitioning);
  sim.run(2.0);
  EXPECT_EQ(sim.status().switch_status, SwitchStatus::Done);
  EXPECT_GT(sim.true_foot(0).z() - robot::kFootRadius, 0.05);
  for (std::size_t leg = 1; leg < kNumLegs; ++leg) EXPECT_LT(sim.true_foot(leg).z() - robot::kFootRadius, 0.005) << leg;
  EXPECT_GT(sim.true_height(), 0.22);
  EXPECT_LT(std::abs(sim.true_rpy().x()), 0.05);
  EXPECT_LT(std::abs(sim.true_rpy().y()), 0.05);
  EXPECT_EQ(sim.status().contact, 0b1110);
  // gait 2 without a lifted leg is refused
  sim.send(command(ModeId::PoseControl, 2), 0.1);
  EXPECT_EQ(sim.status().switch_status, SwitchStatus::BanTransition);
  // put down by a pose command with all feet on the ground
  sim.send(pose(0, 0, 0), 2.5);
  EXPECT_LT(sim.true_foot(0).z() - robot::kFootRadius, 0.005);
  EXPECT_EQ(sim.status().contact, 0x0F);
}

TEST(PoseControlSim, ALiftedFootMovesToANewOffsetAtALimitedSpeed) {
  ModeSim sim;
  stand_in_pose_control(sim);
  HighLevelCommand shake = command(ModeId::PoseControl, 2);
  shake.contact = 0b1110;
  shake.foot_pose = {0.1f, 0.0f, 0.15f, 0.0f, 0.0f, 0.0f};
  sim.send(shake, 2.5);
  const double high = sim.true_foot(0).z();
  // 6 cm down: at 0.4 m/s the target takes 0.15 s; a jump would have the foot there in a few ticks
  shake.foot_pose[2] = 0.09f;
  sim.send(shake, 0.05);
  EXPECT_LT(high - sim.true_foot(0).z(), 0.03);
  sim.run(0.5);
  EXPECT_NEAR(high - sim.true_foot(0).z(), 0.06, 0.01);
}

TEST(PoseControlSim, HoldStopsTheBodyWhereItIs) {
  ModeSim sim;
  stand_in_pose_control(sim);
  sim.send(pose(0.0, 0.0, 0.0, -0.08), 0.3);
  sim.send(command(ModeId::PoseControl, 3), 0.5);
  const double held = sim.true_height();
  EXPECT_LT(held, 0.225);
  EXPECT_GT(held, 0.16);
  sim.run(1.0);
  EXPECT_NEAR(sim.true_height(), held, 0.003);
  EXPECT_EQ(sim.status().gait_id, 3);
  EXPECT_EQ(sim.status().switch_status, SwitchStatus::Done);
}

}  // namespace
}  // namespace cerebellum
