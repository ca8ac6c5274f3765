// Which mode runs and whether a command may change it, with scripted modes.
#include "modes/mode_switcher.hpp"

#include <gtest/gtest.h>

#include "modes/transition_table.hpp"
#include "scripted_machine.hpp"

namespace cerebellum {
namespace {

using testing::cmd;
using testing::ScriptedMode;

struct Switcher {
  Switcher() {
    for (ScriptedMode* m : {&off, &damper, &recovery, &loco}) switcher.add(*m);
  }
  ScriptedMode off{ModeId::Off}, damper{ModeId::PureDamper}, recovery{ModeId::RecoveryStand},
      loco{ModeId::Locomotion, 31};
  ModeSwitcher switcher;
  RobotState state;
};

TEST(ModeSwitcher, FindsOnlyTheModesRegisteredByTheirId) {
  Switcher s;
  EXPECT_EQ(s.switcher.find(ModeId::Locomotion), &s.loco);
  EXPECT_EQ(s.switcher.find(static_cast<int>(ModeId::RecoveryStand)), &s.recovery);
  EXPECT_EQ(s.switcher.find(ModeId::PoseControl), nullptr) << "not registered";
  EXPECT_EQ(s.switcher.find(-1), nullptr);
  EXPECT_EQ(s.switcher.find(kMaxModeId + 1), nullptr);
  EXPECT_FALSE(s.switcher.started());
}

TEST(ModeSwitcher, ASwitchExitsTheRunningModeAndEntersTheNewOneWithItsCommand) {
  Switcher s;
  s.switcher.switch_to(s.off, s.state, cmd(ModeId::Off, 0, 0));
  s.switcher.switch_to(s.recovery, s.state, cmd(ModeId::RecoveryStand, 0, 7));
  EXPECT_EQ(s.off.exited, 1);
  EXPECT_EQ(s.recovery.entered, 1);
  EXPECT_EQ(s.switcher.current_id(), ModeId::RecoveryStand);
  EXPECT_EQ(s.switcher.running_command().life_count, 7);
  s.switcher.update(s.state, cmd(ModeId::RecoveryStand, 0, 8));
  EXPECT_EQ(s.recovery.updated, 1);
  EXPECT_EQ(s.recovery.exited, 0);
  EXPECT_EQ(s.switcher.running_command().life_count, 8);
}

TEST(ModeSwitcher, RefusesASwitchTheTransitionTableForbids) {
  Switcher s;
  s.switcher.switch_to(s.off, s.state, cmd(ModeId::Off, 0, 0));
  ASSERT_FALSE(transition_allowed(ModeId::Off, ModeId::Locomotion));
  const StartRefusal refusal = s.switcher.switch_refusal(s.loco, s.state, cmd(ModeId::Locomotion, 3, 1));
  ASSERT_TRUE(refusal);
  EXPECT_EQ(refusal.status, SwitchStatus::BanTransition);
  ASSERT_TRUE(transition_allowed(ModeId::Off, ModeId::RecoveryStand));
  EXPECT_FALSE(s.switcher.switch_refusal(s.recovery, s.state, cmd(ModeId::RecoveryStand, 0, 1)));
}

TEST(ModeSwitcher, AModeThatMustFinishGivesWayOnlyToDampingAndOff) {
  Switcher s;
  s.switcher.switch_to(s.recovery, s.state, cmd(ModeId::RecoveryStand, 0, 0));
  s.switcher.switch_to(s.loco, s.state, cmd(ModeId::Locomotion, 3, 1));
  s.loco.finishing = true;
  ASSERT_TRUE(transition_allowed(ModeId::Locomotion, ModeId::RecoveryStand));
  EXPECT_TRUE(s.switcher.switch_refusal(s.recovery, s.state, cmd(ModeId::RecoveryStand, 0, 2)));
  EXPECT_FALSE(s.switcher.switch_refusal(s.damper, s.state, cmd(ModeId::PureDamper, 0, 2)));
  EXPECT_FALSE(s.switcher.switch_refusal(s.loco, s.state, cmd(ModeId::Locomotion, 1, 2))) << "an update of itself";
  s.loco.finishing = false;
  EXPECT_FALSE(s.switcher.switch_refusal(s.recovery, s.state, cmd(ModeId::RecoveryStand, 0, 3)));
}

TEST(ModeSwitcher, TheTargetsStartRefusalIsPassedOnWithItsStatus) {
  Switcher s;
  s.switcher.switch_to(s.recovery, s.state, cmd(ModeId::RecoveryStand, 0, 0));
  s.loco.refusal = {SwitchStatus::LowBattery, "battery too low"};
  const StartRefusal refusal = s.switcher.switch_refusal(s.loco, s.state, cmd(ModeId::Locomotion, 3, 1));
  ASSERT_TRUE(refusal);
  EXPECT_EQ(refusal.status, SwitchStatus::LowBattery);
  EXPECT_STREQ(refusal.reason, "battery too low");
}

}  // namespace
}  // namespace cerebellum
