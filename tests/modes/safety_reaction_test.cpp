// What the health protection and the body watch call for, and which commands they refuse.
#include "modes/safety_reaction.hpp"

#include <gtest/gtest.h>

#include "safety/body_watch.hpp"
#include "scripted_machine.hpp"

namespace cerebellum {
namespace {

using testing::cmd;
using testing::ScriptedMode;

HealthVerdict verdict(Protection protection, std::uint32_t causes) {
  HealthVerdict v;
  v.protection = protection;
  v.causes = causes;
  return v;
}

struct Watched {
  Watched() {
    for (ScriptedMode* m : {&damper, &recovery, &loco}) switcher.add(*m);
    state.valid = true;
    for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
      state.foot_position_body[leg] = foot_position_in_body(leg, Vec3(0.0, 0.785, -1.22));
      state.contact[leg] = 1.0;
    }
    switcher.switch_to(loco, state, cmd(ModeId::Locomotion, 3, 1));
  }
  ScriptedMode damper{ModeId::PureDamper}, recovery{ModeId::RecoveryStand}, loco{ModeId::Locomotion, 31};
  ModeSwitcher switcher;
  SafetyReaction reaction;
  RobotState state;
};

TEST(SafetyReaction, DampingProtectionCallsForPureDamperAndAStopForOff) {
  SafetyReaction reaction;
  EXPECT_FALSE(reaction.health_target(ModeId::Locomotion));
  EXPECT_FALSE(reaction.health_status());
  reaction.observe_health(verdict(Protection::Damping, kHealthImuStuck));
  EXPECT_EQ(reaction.health_target(ModeId::Locomotion), ModeId::PureDamper);
  EXPECT_EQ(reaction.health_status(), SwitchStatus::HighDamping);
  EXPECT_FALSE(reaction.health_target(ModeId::PureDamper)) << "already damping";
  EXPECT_FALSE(reaction.health_target(ModeId::Off)) << "damping does not wake motors that are off";
  reaction.observe_health(verdict(Protection::Stopped, kHealthImuStuck));
  EXPECT_EQ(reaction.health_target(ModeId::PureDamper), ModeId::Off);
  EXPECT_EQ(reaction.health_status(), SwitchStatus::EmergencyStop);
}

TEST(SafetyReaction, AHealthProtectionRefusesEveryCommandNamingItsCause) {
  SafetyReaction reaction;
  EXPECT_EQ(reaction.refusal(ModeId::Locomotion, ModeId::QpStand), nullptr);
  reaction.observe_health(verdict(Protection::Damping, kHealthMotorError));
  EXPECT_NE(std::string(reaction.refusal(ModeId::RecoveryStand, ModeId::PureDamper)).find("motor"), std::string::npos);
  reaction.observe_health(verdict(Protection::Damping, kHealthBatteryCritical));
  EXPECT_NE(std::string(reaction.refusal(ModeId::Off, ModeId::PureDamper)).find("battery"), std::string::npos);
  reaction.observe_health(verdict(Protection::Damping, kHealthStateInvalid));
  EXPECT_NE(std::string(reaction.refusal(ModeId::Off, ModeId::PureDamper)).find("sensor"), std::string::npos);
}

TEST(SafetyReaction, ATippedOverWalkingRobotIsDampedAndOnlyARecoveryStandClearsTheLatch) {
  Watched w;
  EXPECT_EQ(w.reaction.watch_body(w.state, w.switcher).action, BodyReaction::Action::None);
  w.state.rpy.x() = kOrientationErrorRad + 0.1;
  const BodyReaction tipped = w.reaction.watch_body(w.state, w.switcher);
  ASSERT_EQ(tipped.action, BodyReaction::Action::Damp);
  EXPECT_EQ(tipped.command.mode, static_cast<int>(ModeId::PureDamper));
  EXPECT_TRUE(w.reaction.orientation_error());
  EXPECT_EQ(w.reaction.protection_status(), SwitchStatus::HighDamping);
  // latched while the robot lies: only a recovery stand, damping or off are let through
  EXPECT_NE(w.reaction.refusal(ModeId::Locomotion, ModeId::PureDamper), nullptr);
  EXPECT_EQ(w.reaction.refusal(ModeId::RecoveryStand, ModeId::PureDamper), nullptr);
  EXPECT_EQ(w.reaction.refusal(ModeId::Off, ModeId::PureDamper), nullptr);
  w.reaction.on_switch(ModeId::PureDamper);
  EXPECT_TRUE(w.reaction.orientation_error()) << "damping does not clear it";
  w.reaction.on_switch(ModeId::RecoveryStand);
  EXPECT_FALSE(w.reaction.orientation_error());
  EXPECT_FALSE(w.reaction.protection_status());
}

TEST(SafetyReaction, AFootOutOfReachWhileWalkingIsAFootPositionError) {
  Watched w;
  w.state.foot_position_body[2].z() = 0.0;  // at the hip's height: far above the workspace
  const BodyReaction reaction = w.reaction.watch_body(w.state, w.switcher);
  ASSERT_EQ(reaction.action, BodyReaction::Action::Damp);
  EXPECT_EQ(w.reaction.foot_position_error(), foot_position_error_bits(w.state));
  EXPECT_NE(w.reaction.foot_position_error(), 0);
  EXPECT_EQ(w.reaction.protection_status(), SwitchStatus::HighDamping);
}

TEST(SafetyReaction, AnUnwatchedModeIsNeverDamped) {
  Watched w;
  w.switcher.switch_to(w.recovery, w.state, cmd(ModeId::RecoveryStand, 0, 2));
  w.state.rpy.x() = kOrientationErrorRad + 0.1;
  EXPECT_EQ(w.reaction.watch_body(w.state, w.switcher).action, BodyReaction::Action::None);
  EXPECT_FALSE(w.reaction.orientation_error());
}

}  // namespace
}  // namespace cerebellum
