// The machine's watch over the standing modes, with scripted modes and synthetic states:
// tipping over latches ori_error and an emergency stop until a recovery stand; being picked up
// enters Lifted and being set down resumes the stand.
#include <gtest/gtest.h>

#include "core/leg_kinematics.hpp"
#include "modes/high_level_machine.hpp"
#include "modes/watched_modes.hpp"

namespace cerebellum {
namespace {

class ScriptedMode final : public Mode {
 public:
  explicit ScriptedMode(ModeId id, bool refuse_all = false) : id_(id), refuse_all_(refuse_all) {}
  ModeId id() const override { return id_; }
  const char* check(const HighLevelCommand&) const override { return refuse_all_ ? "no" : nullptr; }
  void enter(const RobotState&, const HighLevelCommand& c) override { last = c, ++entered; }
  void update(const RobotState&, const HighLevelCommand& c) override { last = c; }
  void run(const RobotState&, JointCommand& command) override { command = JointCommand{}; }
  int gait_id() const override { return last.gait_id; }
  int progress_percent() const override { return 100; }
  HighLevelCommand last;
  int entered = 0;

 private:
  ModeId id_;
  bool refuse_all_;
};

HighLevelCommand cmd(ModeId mode, int gait, int life_count) {
  HighLevelCommand c;
  c.mode = static_cast<int>(mode);
  c.gait_id = gait;
  c.life_count = life_count;
  return c;
}

struct Machine {
  Machine() : machine(0.002, cmd(ModeId::RecoveryStand, 0, 0)) {
    for (ScriptedMode* m : {&off, &damper, &recovery, &qp, &loco, &pose, &lifted}) machine.add_mode(*m);
    standing();
  }
  void standing() {
    state = RobotState{};
    state.valid = true;
    state.contact = {1, 1, 1, 1};
    // feet where a standing robot has them, inside the walking workspace
    for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
      state.foot_position_body[leg] = foot_position_in_body(leg, Vec3(0.0, 0.785, -1.22));
    }
  }
  void tick(int n = 1) {
    for (int i = 0; i < n; ++i) {
      JointCommand command;
      machine.compute(state, command);
      state.time_s += 0.002;
    }
  }
  void send(const HighLevelCommand& c) {
    machine.submit(c, state.time_s);
    tick();
  }
  ScriptedMode off{ModeId::Off}, damper{ModeId::PureDamper}, recovery{ModeId::RecoveryStand}, qp{ModeId::QpStand},
      loco{ModeId::Locomotion}, pose{ModeId::PoseControl}, lifted{ModeId::Lifted, true};
  HighLevelMachine machine;
  RobotState state;
};

TEST(WatchedModes, AreTheModesThatStandOnTheirFeet) {
  EXPECT_TRUE(watches_body(ModeId::QpStand) && watches_body(ModeId::Locomotion) && watches_body(ModeId::PoseControl));
  EXPECT_FALSE(watches_body(ModeId::RecoveryStand) || watches_body(ModeId::PureDamper) || watches_body(ModeId::Off));
  EXPECT_TRUE(watches_feet(ModeId::Locomotion));
  EXPECT_FALSE(watches_feet(ModeId::QpStand) || watches_feet(ModeId::PoseControl));
}

TEST(BodyWatch, TippingOverInAStandingModeLatchesTheHighDampingProtectionUntilARecoveryStand) {
  Machine m;
  m.tick();
  m.send(cmd(ModeId::QpStand, 0, 1));
  EXPECT_EQ(m.machine.status().mode, 3);
  m.state.rpy = {1.35, 0.0, 0.0};
  m.tick();
  EXPECT_EQ(m.machine.status().mode, 7);
  EXPECT_EQ(m.machine.status().ori_error, 1);
  EXPECT_EQ(m.machine.status().switch_status, SwitchStatus::HighDamping);
  // lying on its side now, upright again: still latched; anything but a stand is refused
  m.state.rpy = {0.0, 0.0, 0.0};
  m.send(cmd(ModeId::PoseControl, 0, 2));
  EXPECT_EQ(m.machine.status().mode, 7);
  EXPECT_EQ(m.pose.entered, 0);
  EXPECT_EQ(m.machine.status().switch_status, SwitchStatus::HighDamping);
  m.send(cmd(ModeId::RecoveryStand, 0, 3));
  EXPECT_EQ(m.machine.status().mode, 12);
  EXPECT_EQ(m.machine.status().ori_error, 0);
  EXPECT_EQ(m.machine.status().switch_status, SwitchStatus::Done);
}

TEST(BodyWatch, RecoveryStandItselfIsNotWatched) {
  Machine m;
  m.state.rpy = {3.1, 0.0, 0.0};  // upside down while it rights itself
  m.tick(10);
  EXPECT_EQ(m.machine.status().mode, 12);
  EXPECT_EQ(m.machine.status().ori_error, 0);
}

TEST(BodyWatch, PickedUpRobotGoesToLiftedAndBackToItsStandWhenSetDown) {
  Machine m;
  m.tick();
  HighLevelCommand walk = cmd(ModeId::Locomotion, 27, 1);
  walk.vel_des = {0.3f, 0.0f, 0.0f};
  m.send(walk);
  EXPECT_EQ(m.machine.status().mode, 11);
  // feet off the ground while the body is pulled up at 3 m/s^2 for 0.2 s
  m.state.contact = {0, 0, 0, 0};
  m.state.accel_world = {0.0, 0.0, 3.0};
  m.tick(100);
  EXPECT_EQ(m.machine.status().mode, 9);
  EXPECT_EQ(m.machine.status().switch_status, SwitchStatus::Lifted);
  // held still in the air: a stand cannot be asked for, a damper can
  m.state.accel_world.setZero();
  m.send(cmd(ModeId::QpStand, 0, 2));
  EXPECT_EQ(m.machine.status().mode, 9);
  EXPECT_EQ(m.machine.status().switch_status, SwitchStatus::BanTransition);
  // set down: feet carry the robot again for 0.1 s; walking resumes as a stand (gait 1)
  m.state.contact = {1, 1, 1, 1};
  m.tick(60);
  EXPECT_EQ(m.machine.status().mode, 11);
  EXPECT_EQ(m.loco.last.gait_id, 1);
  EXPECT_EQ(m.loco.last.vel_des[0], 0.0f);
}

TEST(BodyWatch, AFallIsNotALift) {
  Machine m;
  m.tick();
  m.send(cmd(ModeId::PoseControl, 0, 1));
  // no foot loaded, but the body is in free fall
  m.state.contact = {0, 0, 0, 0};
  m.state.accel_world = {0.0, 0.0, -9.81};
  m.tick(110);
  EXPECT_EQ(m.machine.status().mode, 21);
  // and lying still on the belly with unloaded feet is not a lift either (within the heartbeat)
  m.state.accel_world.setZero();
  m.tick(110);
  EXPECT_EQ(m.machine.status().mode, 21);
}

TEST(BodyWatch, PoseControlResumesAsQpStandAfterALift) {
  EXPECT_EQ(command_after_landing(cmd(ModeId::PoseControl, 2, 5)).mode, 3);
  EXPECT_EQ(command_after_landing(cmd(ModeId::PoseControl, 2, 5)).gait_id, 1);
  HighLevelCommand qp = cmd(ModeId::QpStand, 0, 5);
  qp.rpy_des = {0.1f, 0.0f, 0.0f};
  qp.contact = 0b1110;
  qp.duration = 500;
  const HighLevelCommand after = command_after_landing(qp);
  EXPECT_EQ(after.mode, 3);
  EXPECT_EQ(after.gait_id, 1);
  EXPECT_EQ(after.rpy_des[0], 0.1f);
  EXPECT_EQ(after.contact, 0x0F);
  EXPECT_EQ(after.duration, 0);
  EXPECT_EQ(command_after_landing(cmd(ModeId::Locomotion, 31, 5)).gait_id, 31);
}

}  // namespace
}  // namespace cerebellum
