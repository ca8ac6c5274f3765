// The state machine with scripted modes: switching, refusals, timeouts, status.
#include "modes/high_level_machine.hpp"

#include <gtest/gtest.h>

#include <optional>
#include <string>

#include "modes/scripted_machine.hpp"

namespace cerebellum {
namespace {

using testing::cmd;
using testing::Machine;

TEST(HighLevelMachine, StartsInTheStartupModeAndRunsIt) {
  Machine m(ModeId::RecoveryStand);
  const JointCommand command = m.tick();
  EXPECT_EQ(command.kp[0], 12.0);
  EXPECT_EQ(m.machine.status().mode, 12);
  EXPECT_EQ(m.recovery.entered, 1);
}

TEST(HighLevelMachine, ACommandBeyondTheFullQueueIsRefusedInTheResponseAndNoted) {
  Machine m(ModeId::RecoveryStand);
  m.tick();
  // timed pose commands, handed over as fast as the inbox takes them (8 a tick)
  const int sent = static_cast<int>(CommandQueue::kCapacity) + 3;
  for (int i = 1; i <= sent; ++i) {
    m.machine.submit(cmd(ModeId::PoseControl, 0, i % 250 + 1, 1000), m.state.time_s);
    if (i % 8 == 0) m.tick();
  }
  m.tick();
  EXPECT_GE(m.machine.counters().queue_full.load(), 1u);
  EXPECT_EQ(m.machine.status().switch_status, SwitchStatus::BanTransition);
  bool noted = false;
  while (const std::optional<ClientNote> note = m.machine.refusals().try_pop()) {
    noted = noted || std::string(note->reason).find("queue is full") != std::string::npos;
  }
  EXPECT_TRUE(noted);
}

TEST(HighLevelMachine, TheQueueHoldsTheSeedsCustomizedGaitExample) {
  // its steps, then 75 timed "heartbeats" (new life_counts): about 90 timed entries
  Machine m(ModeId::RecoveryStand);
  m.tick();
  for (int i = 1; i <= 90; ++i) {
    m.machine.submit(cmd(ModeId::PoseControl, 0, i, 200), m.state.time_s);
    if (i % 8 == 0) m.tick();
  }
  m.tick();
  EXPECT_EQ(m.machine.counters().queue_full.load(), 0u);
  EXPECT_EQ(m.machine.counters().new_commands.load(), 90u);
}

TEST(HighLevelMachine, ContactPlanIsTheRunningModes) {
  Machine m(ModeId::Locomotion);
  m.loco.plan = ContactSchedule{{{1.0, 0.25}, {0.0, 0.0}, {0.0, 0.0}, {1.0, 0.25}}};
  m.tick();
  ASSERT_TRUE(m.machine.contact_plan().has_value());
  EXPECT_EQ((*m.machine.contact_plan())[0].stance_phase, 0.25);
  m.machine.submit(cmd(ModeId::PureDamper, 0, 1), m.state.time_s);
  m.tick();
  EXPECT_EQ(m.machine.status().mode, static_cast<int>(ModeId::PureDamper));
  EXPECT_FALSE(m.machine.contact_plan().has_value());
}

TEST(HighLevelMachine, LegalSwitchRunsTheNewModeAndReportsIt) {
  Machine m;
  m.tick();
  m.machine.submit(cmd(ModeId::RecoveryStand, 0, 1), m.state.time_s);
  m.recovery.progress = 40;
  m.tick();
  EXPECT_EQ(m.machine.status().mode, 12);
  EXPECT_EQ(m.machine.status().order_process_bar, 40);
  EXPECT_EQ(m.machine.status().switch_status, SwitchStatus::Transitioning);
  m.recovery.progress = 100;
  m.tick();
  EXPECT_EQ(m.machine.status().switch_status, SwitchStatus::Done);
}

TEST(HighLevelMachine, AModeThatGaveUpAndDampsIsReportedAsHighDampingUntilItRecovers) {
  Machine m(ModeId::Locomotion);
  m.tick();
  EXPECT_EQ(m.machine.status().switch_status, SwitchStatus::Done);
  m.loco.damping = true;
  m.tick();
  EXPECT_EQ(m.machine.status().mode, 11);
  EXPECT_EQ(m.machine.status().switch_status, SwitchStatus::HighDamping);
  m.loco.damping = false;
  m.tick();
  EXPECT_EQ(m.machine.status().switch_status, SwitchStatus::Done);
}

TEST(HighLevelMachine, AModeTheRobotsStateForbidsIsRefusedWithItsOwnStatusAndTheOldModeRuns) {
  Machine m(ModeId::Locomotion);
  m.tick();
  m.pose.refusal = {SwitchStatus::OverHeat, "too hot"};
  m.machine.submit(cmd(ModeId::PoseControl, 0, 1), m.state.time_s);
  m.tick();
  EXPECT_EQ(m.machine.status().mode, 11);
  EXPECT_EQ(m.machine.status().switch_status, SwitchStatus::OverHeat);
  EXPECT_EQ(m.pose.entered, 0);
  const auto note = m.machine.refusals().try_pop();
  ASSERT_TRUE(note.has_value());
  EXPECT_STREQ(note->reason, "too hot");
  // once the state allows it, the same mode starts
  m.pose.refusal = {};
  m.machine.submit(cmd(ModeId::PoseControl, 0, 2), m.state.time_s);
  m.tick();
  EXPECT_EQ(m.machine.status().mode, 21);
  EXPECT_EQ(m.machine.status().switch_status, SwitchStatus::Done);
  // a switch the table forbids is refused as such first (PoseControl -> PureDamper is allowed,
  // Off -> Locomotion is not)
  Machine off;
  off.tick();
  off.loco.refusal = {SwitchStatus::LowBattery, "low"};
  off.machine.submit(cmd(ModeId::Locomotion, 1, 1), off.state.time_s);
  off.tick();
  EXPECT_EQ(off.machine.status().switch_status, SwitchStatus::BanTransition);
}

TEST(HighLevelMachine, IllegalSwitchIsBannedAndKeepsTheOldMode) {
  Machine m;
  m.tick();
  m.machine.submit(cmd(ModeId::Locomotion, 27, 1), m.state.time_s);  // 0 -> 11 is not in the table
  const JointCommand command = m.tick();
  EXPECT_EQ(command.kp[0], 0.0);
  EXPECT_EQ(m.machine.status().mode, 0);
  EXPECT_EQ(m.machine.status().switch_status, SwitchStatus::BanTransition);
  EXPECT_EQ(m.loco.entered, 0);
  EXPECT_EQ(m.machine.counters().banned_transitions.load(), 1u);
  const auto note = m.machine.refusals().try_pop();
  ASSERT_TRUE(note.has_value());
  EXPECT_EQ(note->mode, 11);
  EXPECT_EQ(note->from_mode, 0);
  // the next accepted command clears the ban
  m.machine.submit(cmd(ModeId::RecoveryStand, 0, 2), m.state.time_s);
  m.tick();
  EXPECT_EQ(m.machine.status().switch_status, SwitchStatus::Done);
}

TEST(HighLevelMachine, UnknownModeUnavailableModeAndBadGaitAreBanned) {
  for (const HighLevelCommand& c :
       {cmd(static_cast<ModeId>(99), 0, 1), cmd(ModeId::Jump3d, 0, 1), cmd(ModeId::PureDamper, 4, 1)}) {
    Machine m;
    m.tick();
    m.machine.submit(c, m.state.time_s);
    m.tick();
    EXPECT_EQ(m.machine.status().mode, 0) << c.mode;
    EXPECT_EQ(m.machine.status().switch_status, SwitchStatus::BanTransition) << c.mode;
  }
}

TEST(HighLevelMachine, SameModeCommandUpdatesTheRunningMode) {
  Machine m(ModeId::RecoveryStand);
  m.tick();
  m.machine.submit(cmd(ModeId::Locomotion, 27, 1), m.state.time_s);
  m.tick();
  m.machine.submit(cmd(ModeId::Locomotion, 3, 2), m.state.time_s);
  m.tick();
  EXPECT_EQ(m.loco.entered, 1);
  EXPECT_EQ(m.loco.updated, 1);
  EXPECT_EQ(m.machine.status().gait_id, 3);
}

TEST(HighLevelMachine, SilentClientSendsTheRobotToPureDamperAfterHalfASecond) {
  Machine m(ModeId::RecoveryStand);
  m.tick();
  m.machine.submit(cmd(ModeId::PoseControl, 0, 1), m.state.time_s);
  for (int i = 0; i < 250; ++i) m.tick();  // 0.5 s
  EXPECT_EQ(m.machine.status().mode, 21);
  m.tick();
  m.tick();
  EXPECT_EQ(m.machine.status().mode, 7);
  EXPECT_EQ(m.machine.counters(HighLevelSource::CyberDog2Lcm).timeouts.load(), 1u);
}

TEST(HighLevelMachine, SilentClientLeavesOffAlone) {
  Machine m;
  m.tick();
  m.machine.submit(cmd(ModeId::Off, 0, 1), m.state.time_s);
  for (int i = 0; i < 400; ++i) m.tick();
  EXPECT_EQ(m.machine.status().mode, 0);
  EXPECT_EQ(m.damper.entered, 0);
}

TEST(HighLevelMachine, LowLevelLatchOnlyFromOffOrPureDamper) {
  Machine m(ModeId::RecoveryStand);
  m.tick();
  EXPECT_FALSE(m.machine.allows_low_level_latch());
  m.machine.submit(cmd(ModeId::PureDamper, 0, 1), m.state.time_s);
  m.tick();
  EXPECT_TRUE(m.machine.allows_low_level_latch());
  m.machine.on_handover();
  m.tick();
  EXPECT_EQ(m.machine.status().mode, 15);
}

TEST(HighLevelMachine, TimedSequenceWaitsForEachSwitchToFinish) {
  Machine m(ModeId::RecoveryStand);
  m.tick();
  m.pose.progress = 0;
  m.machine.submit(cmd(ModeId::PoseControl, 0, 1, 10), m.state.time_s);  // 5 ticks once switched
  m.machine.submit(cmd(ModeId::Locomotion, 1, 2, 10), m.state.time_s);
  for (int i = 0; i < 20; ++i) m.tick();
  EXPECT_EQ(m.machine.status().mode, 21);  // still switching: time does not run
  m.pose.progress = 100;
  for (int i = 0; i < 5; ++i) m.tick();
  EXPECT_EQ(m.machine.status().mode, 21);
  m.tick();
  EXPECT_EQ(m.machine.status().mode, 11);
}

TEST(HighLevelMachine, FootOutOfItsWorkspaceWhileWalkingDampsUntilRecoveryStand) {
  Machine m(ModeId::RecoveryStand);
  m.tick();
  m.machine.submit(cmd(ModeId::Locomotion, 3, 1), m.state.time_s);
  m.tick();
  EXPECT_EQ(m.machine.status().mode, 11);
  m.state.foot_position_body[2].x() -= 0.4;  // RR far behind
  m.tick();
  EXPECT_EQ(m.machine.status().mode, 7);
  EXPECT_EQ(m.machine.status().footpos_error, 1 << 6);
  EXPECT_EQ(m.machine.status().switch_status, SwitchStatus::HighDamping);
  // walking again is refused until a recovery stand
  m.machine.submit(cmd(ModeId::Locomotion, 3, 2), m.state.time_s);
  m.tick();
  EXPECT_EQ(m.machine.status().mode, 7);
  m.state.foot_position_body[2].x() += 0.4;
  m.machine.submit(cmd(ModeId::RecoveryStand, 0, 3), m.state.time_s);
  m.tick();
  EXPECT_EQ(m.machine.status().mode, 12);
  EXPECT_EQ(m.machine.status().footpos_error, 0);
}

TEST(HighLevelMachine, ContactBitsComeFromTheEstimate) {
  Machine m;
  m.state.contact = {1.0, 0.0, 1.0, 1.0};
  m.tick();
  EXPECT_EQ(m.machine.status().contact, 0b1101);
  for (std::uint32_t e : m.machine.status().motor_faults) EXPECT_EQ(e, kMotorOk);
}

TEST(HighLevelMachine, ARefusedCommandLeavesTheQueueAsIfItHadNeverBeenSent) {
  Machine m(ModeId::RecoveryStand);
  m.tick();
  m.machine.submit(cmd(ModeId::Locomotion, 10, 1), m.state.time_s);
  m.tick();
  ASSERT_EQ(m.machine.status().mode, 11);
  // two-leg stand with a duration: not in this machine, refused
  m.machine.submit(cmd(ModeId::TwoLegStand, 0, 2, 2000), m.state.time_s);
  m.tick();
  EXPECT_EQ(m.machine.status().switch_status, SwitchStatus::BanTransition);
  const int updates = m.loco.updated;
  // the trot goes on past the refused entry's duration: no hold, no update, heartbeats only
  for (int i = 0; i < 1500; ++i) {
    if (i % 50 == 0) m.machine.submit(cmd(ModeId::TwoLegStand, 0, 2, 2000), m.state.time_s);
    m.tick();
  }
  EXPECT_EQ(m.machine.status().mode, 11);
  EXPECT_EQ(m.machine.status().gait_id, 10);
  EXPECT_EQ(m.loco.updated, updates);
  EXPECT_EQ(m.pose.entered, 0);
}

TEST(HighLevelMachine, ARefusedMotionAfterAStandLeavesTheStandRunning) {
  Machine m(ModeId::RecoveryStand);
  m.tick();
  m.machine.submit(cmd(ModeId::RecoveryStand, 0, 1), m.state.time_s);
  m.tick();
  m.machine.submit(cmd(ModeId::Motion, 2, 2), m.state.time_s);  // duration 0, as the seed sends it
  for (int i = 0; i < 100; ++i) {
    if (i % 50 == 0) m.machine.submit(cmd(ModeId::Motion, 2, 2), m.state.time_s);
    m.tick();
  }
  EXPECT_EQ(m.machine.status().mode, 12);
  EXPECT_EQ(m.pose.entered, 0);  // no 21/3 hold nobody asked for
  // the next command behind it runs at once, as if the refused one had not been sent
  m.machine.submit(cmd(ModeId::PoseControl, 0, 3, 500), m.state.time_s);
  m.tick();
  EXPECT_EQ(m.machine.status().mode, 21);
  EXPECT_EQ(m.machine.status().gait_id, 0);
}

// a low-level client that wants the robot from the first tick and commands nothing
class GreedySource final : public LowLevelSource {
 public:
  const char* name() const override { return "the test client"; }
  bool wants_control() const override { return true; }
  void on_latched(const RobotState&) override {}
  void on_refused(const char*) override {}
  void compute(const RobotState&, JointCommand& command) override { command = JointCommand{}; }
};

TEST(HighLevelMachine, WhileALowLevelClientHoldsTheRobotTheResponseIsLiveAndNewCommandsAreBanned) {
  Machine m(ModeId::PureDamper);
  SourceArbiter arbiter(m.machine);
  JointCommand command;
  arbiter.compute(m.state, command);  // the machine starts in PureDamper
  GreedySource client;
  arbiter.add_low_level_source(client);
  arbiter.compute(m.state, command);
  ASSERT_EQ(arbiter.latched(), &client);

  // live contacts and orientation, mode 15
  m.state.contact = {1.0, 1.0, 0.0, 0.0};
  m.state.rpy.x() = 3.0;  // upside down
  arbiter.compute(m.state, command);
  EXPECT_EQ(m.machine.status().mode, 15);
  EXPECT_EQ(m.machine.status().contact, 0b0011);
  EXPECT_EQ(m.machine.status().ori_error, 1);
  EXPECT_EQ(m.machine.status().switch_status, SwitchStatus::Done);
  for (std::uint32_t e : m.machine.status().motor_faults) EXPECT_EQ(e, kMotorOk);

  // a new command is refused (BAN_TRANS) and counted, with the holder named for the log
  m.machine.submit(cmd(ModeId::RecoveryStand, 0, 1), m.state.time_s);
  arbiter.compute(m.state, command);
  EXPECT_EQ(m.machine.status().mode, 15);
  EXPECT_EQ(m.machine.status().switch_status, SwitchStatus::BanTransition);
  EXPECT_EQ(m.machine.counters().banned_transitions.load(), 1u);
  EXPECT_EQ(m.recovery.entered, 0);
  const auto note = m.machine.refusals().try_pop();
  ASSERT_TRUE(note.has_value());
  EXPECT_EQ(note->mode, 12);
  EXPECT_EQ(note->from_mode, 15);
  EXPECT_STREQ(note->holder, "the test client");

  // heartbeats of the same life_count are no refusals, and a stream of them never overflows
  for (int i = 0; i < 1000; ++i) {
    EXPECT_TRUE(m.machine.submit(cmd(ModeId::RecoveryStand, 0, 1), m.state.time_s));
    arbiter.compute(m.state, command);
  }
  EXPECT_EQ(m.machine.counters().banned_transitions.load(), 1u);
  EXPECT_EQ(m.machine.input_counters(HighLevelSource::CyberDog2Lcm).ring_overflow.load(), 0u);
  EXPECT_EQ(m.machine.counters(HighLevelSource::CyberDog2Lcm).timeouts.load(), 0u);
  m.machine.submit(cmd(ModeId::Locomotion, 3, 2), m.state.time_s);
  arbiter.compute(m.state, command);
  EXPECT_EQ(m.machine.counters().banned_transitions.load(), 2u);
  m.state.rpy.x() = 0.0;
  arbiter.compute(m.state, command);
  EXPECT_EQ(m.machine.status().ori_error, 0);
  EXPECT_EQ(m.machine.status().mode, 15);
}

}  // namespace
}  // namespace cerebellum

namespace cerebellum {
namespace {

using testing::cmd;
using testing::Machine;

// the lease: one high-level client at a time
TEST(HighLevelLease, TheFirstClientHoldsTheRobotAndTheOtherIsRefusedWithItsReason) {
  Machine m(ModeId::RecoveryStand);
  m.tick();
  m.machine.submit(cmd(ModeId::Locomotion, 3, 1), m.state.time_s, HighLevelSource::AlienGoUdp);
  m.tick();
  ASSERT_EQ(m.machine.status().mode, 11);
  ASSERT_EQ(m.machine.holder(), HighLevelSource::AlienGoUdp);
  while (m.machine.refusals().try_pop()) {
  }
  // the LCM client speaks while the UDP client streams: refused, seen as BAN_TRANS, named holder
  for (int i = 0; i < 10; ++i) {
    m.machine.submit(cmd(ModeId::PureDamper, 0, 7), m.state.time_s, HighLevelSource::CyberDog2Lcm);
    m.machine.submit(cmd(ModeId::Locomotion, 3, 1), m.state.time_s, HighLevelSource::AlienGoUdp);
    m.tick();
  }
  EXPECT_EQ(m.machine.status().mode, 11);
  EXPECT_EQ(m.machine.status().switch_status, SwitchStatus::BanTransition);
  EXPECT_EQ(m.machine.counters(HighLevelSource::CyberDog2Lcm).refused_not_holder.load(), 10u);
  const auto note = m.machine.refusals().try_pop();
  ASSERT_TRUE(note.has_value());
  EXPECT_STREQ(note->holder, source_name(HighLevelSource::AlienGoUdp));
  EXPECT_FALSE(m.machine.refusals().try_pop().has_value()) << "one note per new command, not per packet";
}

TEST(HighLevelLease, PassesToTheOtherClientOnceTheHolderIsSilentPastTheTimeout) {
  Machine m(ModeId::RecoveryStand);
  m.tick();
  m.machine.submit(cmd(ModeId::Locomotion, 3, 1), m.state.time_s, HighLevelSource::CyberDog2Lcm);
  m.tick();
  ASSERT_EQ(m.machine.holder(), HighLevelSource::CyberDog2Lcm);
  // silent for longer than the heartbeat timeout: the MC damps; the UDP client may take over
  for (int i = 0; i < 300; ++i) m.tick();
  EXPECT_EQ(m.machine.status().mode, 7);
  m.machine.submit(cmd(ModeId::RecoveryStand, 0, 1), m.state.time_s, HighLevelSource::AlienGoUdp);
  m.tick();
  EXPECT_EQ(m.machine.holder(), HighLevelSource::AlienGoUdp);
  EXPECT_EQ(m.machine.status().mode, 12);
  EXPECT_EQ(m.machine.machine_counters().lease_handovers.load(), 1u);
  EXPECT_EQ(m.machine.counters(HighLevelSource::AlienGoUdp).refused_not_holder.load(), 0u);
}

}  // namespace
}  // namespace cerebellum
