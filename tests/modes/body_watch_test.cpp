// The machine's watch over the standing modes, with scripted modes and synthetic states:
// tipping over latches ori_error and an emergency stop until a recovery stand; being picked up
// enters Lifted and being set down resumes the stand.
#include <gtest/gtest.h>

#include "modes/body_watch.hpp"
#include "modes/high_level_machine.hpp"
#include "modes/lift_detector.hpp"

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

TEST(OrientationError, IsAtOrBeyondTheLimitInRollOrPitch) {
  RobotState s;
  s.rpy = {1.29, 0.0, 3.0};
  EXPECT_FALSE(orientation_error(s));
  s.rpy = {-1.3, 0.0, 0.0};
  EXPECT_TRUE(orientation_error(s));
  s.rpy = {0.0, 1.31, 0.0};
  EXPECT_TRUE(orientation_error(s));
  EXPECT_TRUE(watches_body(ModeId::QpStand) && watches_body(ModeId::Locomotion) && watches_body(ModeId::PoseControl));
  EXPECT_FALSE(watches_body(ModeId::RecoveryStand) || watches_body(ModeId::PureDamper) || watches_body(ModeId::Off));
}

TEST(BodyWatch, TippingOverInAStandingModeLatchesAnEmergencyStopUntilARecoveryStand) {
  Machine m;
  m.tick();
  m.send(cmd(ModeId::QpStand, 0, 1));
  EXPECT_EQ(m.machine.status().mode, 3);
  m.state.rpy = {1.35, 0.0, 0.0};
  m.tick();
  EXPECT_EQ(m.machine.status().mode, 7);
  EXPECT_EQ(m.machine.status().ori_error, 1);
  EXPECT_EQ(m.machine.status().switch_status, SwitchStatus::EmergencyStop);
  // lying on its side now, upright again: still latched; anything but a stand is refused
  m.state.rpy = {0.0, 0.0, 0.0};
  m.send(cmd(ModeId::PoseControl, 0, 2));
  EXPECT_EQ(m.machine.status().mode, 7);
  EXPECT_EQ(m.pose.entered, 0);
  EXPECT_EQ(m.machine.status().switch_status, SwitchStatus::EmergencyStop);
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

TEST(LiftDetector, NeedsUnloadedFeetSupportAndRiseTogether) {
  LiftDetector detector;
  RobotState s;
  s.contact = {0, 0, 0, 0};
  // supported but not rising (lying on the belly): never
  for (int i = 0; i < 500; ++i, s.time_s += 0.002) EXPECT_FALSE(detector.lifted(s));
  // rising at 2 m/s^2 with unloaded feet: after the rise threshold and 0.1 s unloaded
  detector.reset();
  s.accel_world = {0.0, 0.0, 2.0};
  double lifted_at = -1.0;
  const double start = s.time_s;
  for (int i = 0; i < 500 && lifted_at < 0.0; ++i, s.time_s += 0.002) {
    if (detector.lifted(s)) lifted_at = s.time_s - start;
  }
  // 0.2 m/s at 2 m/s^2 (less the leak) takes a little over 0.1 s
  EXPECT_GT(lifted_at, 0.098);
  EXPECT_LT(lifted_at, 0.15);
  // one loaded foot resets the count
  detector.reset();
  s.contact = {1, 0, 0, 0};
  for (int i = 0; i < 500; ++i, s.time_s += 0.002) EXPECT_FALSE(detector.lifted(s));
}

TEST(LiftDetector, LandsWithThreeLoadedFeetHeldForATenthOfASecond) {
  LiftDetector detector;
  RobotState s;
  s.contact = {1, 1, 0, 0};
  for (int i = 0; i < 100; ++i, s.time_s += 0.002) EXPECT_FALSE(detector.landed(s));
  s.contact = {1, 1, 1, 0};
  int ticks = 0;
  while (!detector.landed(s) && ticks < 1000) ++ticks, s.time_s += 0.002;
  EXPECT_NEAR(ticks, 50, 1);
}

}  // namespace
}  // namespace cerebellum

namespace cerebellum {
namespace {

RobotState standing_feet() {
  RobotState state;
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
    state.foot_position_body[leg] = foot_position_in_body(leg, Vec3(0.0, 0.785, -1.22));
  }
  return state;
}

TEST(FootWorkspace, BoundsAreTheInterfaceFormulas) {
  const FootWorkspace w;
  EXPECT_NEAR(w.forward_m, 0.2546, 1e-4);
  EXPECT_NEAR(w.lateral_m, 0.294 * 0.62879 + 0.094 * 0.77757, 1e-4);
  EXPECT_NEAR(w.lowest_m, -0.3087, 1e-4);
  EXPECT_NEAR(w.highest_m, -0.049, 1e-6);
}

TEST(FootWorkspace, StandingFeetAreInsideAndEachAxisHasItsBit) {
  EXPECT_EQ(foot_position_error_bits(standing_feet()), 0);
  RobotState state = standing_feet();
  state.foot_position_body[0].x() += 0.3;   // FR forward
  state.foot_position_body[1].y() += 0.3;   // FL lateral
  state.foot_position_body[3].z() = -0.02;  // RL too high
  EXPECT_EQ(foot_position_error_bits(state), (1 << 0) | (1 << 4) | (1 << 11));
}

}  // namespace
}  // namespace cerebellum
