// The gamepad's mapping (teleop/pad_mapping), checked against numbers worked out by hand from the
// reference's gait table (slow trot 27: vx -0.6..0.6 m/s, vy -0.2..0.2 m/s, yaw -1.3..1.3 rad/s)
#include "teleop/pad_mapping.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

namespace cerebellum {
namespace {

PadState press(PadButton button) {
  PadState pad;
  pad.pressed[static_cast<std::size_t>(button)] = true;
  return pad;
}

PadState sticks(double left_x, double left_y, double right_x) {
  PadState pad;
  pad.left_x = left_x;
  pad.left_y = left_y;
  pad.right_x = right_x;
  return pad;
}

TEST(PadMapping, NothingIsSentBeforeTheFirstButton) {
  PadMapping mapping;
  EXPECT_FALSE(mapping.next(sticks(0.0, 1.0, 0.0)).is_new);
  EXPECT_FALSE(mapping.stop().is_new);
}

TEST(PadMapping, EachButtonSendsItsMode) {
  PadMapping mapping;
  const DriveStep stand = mapping.next(press(PadButton::A));
  EXPECT_TRUE(stand.is_new);
  EXPECT_EQ(stand.command.mode, 12);
  EXPECT_EQ(stand.command.gait_id, 0);
  EXPECT_EQ(mapping.next(press(PadButton::X)).command.mode, 7);
  EXPECT_EQ(mapping.next(press(PadButton::X)).command.gait_id, 1);
  const DriveStep motion = mapping.next(press(PadButton::RightShoulder));
  EXPECT_EQ(motion.command.mode, 62);
  EXPECT_EQ(motion.command.gait_id, 4);
  const DriveStep jump = mapping.next(press(PadButton::LeftShoulder));
  EXPECT_EQ(jump.command.mode, 16);
  EXPECT_EQ(jump.command.gait_id, 6);
}

TEST(PadMapping, DampWinsOverEveryOtherButtonPressedInTheSameSampleAndWorksFromEveryMode) {
  for (const PadButton before :
       {PadButton::A, PadButton::X, PadButton::Y, PadButton::RightShoulder, PadButton::LeftShoulder}) {
    PadMapping mapping;
    mapping.next(press(before));
    PadState all;
    all.pressed.fill(true);
    const DriveStep damp = mapping.next(all);
    EXPECT_TRUE(damp.is_new);
    EXPECT_EQ(damp.command.mode, 7);
    EXPECT_EQ(damp.command.gait_id, 0);
  }
}

TEST(PadMapping, TheSameButtonTwiceIsTwoNewCommandsSoASecondJumpJumps) {
  PadMapping mapping;
  EXPECT_TRUE(mapping.next(press(PadButton::LeftShoulder)).is_new);
  EXPECT_TRUE(mapping.next(press(PadButton::LeftShoulder)).is_new);
}

TEST(PadMapping, FullLeftStickForwardFromAStandWalksTheSlowTrotAtItsTopSpeed) {
  PadMapping mapping;
  mapping.next(press(PadButton::A));
  const DriveStep walk = mapping.next(sticks(0.0, 1.0, 0.0));
  EXPECT_TRUE(walk.is_new);
  EXPECT_EQ(walk.command.mode, 11);
  EXPECT_EQ(walk.command.gait_id, 27);
  EXPECT_FLOAT_EQ(walk.command.vel_des[0], 0.6f);
  EXPECT_FLOAT_EQ(walk.command.vel_des[1], 0.0f);
  EXPECT_FLOAT_EQ(walk.command.vel_des[2], 0.0f);
  EXPECT_GT(walk.command.step_height[0], 0.0f);
}

TEST(PadMapping, StickRightMeansMovingAndTurningRightWhichAreNegativeYAndYaw) {
  PadMapping mapping;
  mapping.next(press(PadButton::A));
  const DriveStep walk = mapping.next(sticks(1.0, -1.0, 1.0));
  EXPECT_FLOAT_EQ(walk.command.vel_des[0], -0.6f);
  EXPECT_FLOAT_EQ(walk.command.vel_des[1], -0.2f);
  EXPECT_FLOAT_EQ(walk.command.vel_des[2], -1.3f);
  const DriveStep left = mapping.next(sticks(-1.0, 0.0, -1.0));
  EXPECT_FLOAT_EQ(left.command.vel_des[1], 0.2f);
  EXPECT_FLOAT_EQ(left.command.vel_des[2], 1.3f);
}

TEST(PadMapping, RightStickUpRaisesTheHeadAndTheTriggersSetTheBodyHeightInModeElevensRanges) {
  // mode 11: pitch -0.25..0.3 rad (+: head up), height 0.2..0.28 m, 0.235 m by default
  PadMapping mapping;
  mapping.next(press(PadButton::A));
  PadState pad;
  pad.right_y = 1.0;
  const DriveStep up = mapping.next(pad);
  EXPECT_TRUE(up.is_new);
  EXPECT_EQ(up.command.mode, 11);
  EXPECT_FLOAT_EQ(up.command.rpy_des[1], 0.3f);
  EXPECT_FLOAT_EQ(up.command.pos_des[2], 0.235f);
  EXPECT_EQ(up.command.vel_des, (std::array<float, 3>{0.0f, 0.0f, 0.0f}));
  pad.right_y = -1.0;
  pad.right_trigger = 1.0;
  const DriveStep high = mapping.next(pad);
  EXPECT_FLOAT_EQ(high.command.rpy_des[1], -0.25f);
  EXPECT_FLOAT_EQ(high.command.pos_des[2], 0.28f);
  pad = PadState{};
  pad.left_trigger = 1.0;
  EXPECT_FLOAT_EQ(mapping.next(pad).command.pos_des[2], 0.2f);
  EXPECT_FLOAT_EQ(mapping.next(PadState{}).command.pos_des[2], 0.235f);  // released: the default height
}

TEST(PadMapping, TheDeadZoneIsZeroAndTheDriveStartsFromZeroAtItsEdge) {
  EXPECT_EQ(stick_after_dead_zone(0.1), 0.0);
  EXPECT_EQ(stick_after_dead_zone(-0.15), 0.0);
  EXPECT_NEAR(stick_after_dead_zone(0.575), 0.5, 1e-12);  // (0.575 - 0.15) / 0.85
  EXPECT_NEAR(stick_after_dead_zone(-0.575), -0.5, 1e-12);
  EXPECT_EQ(stick_after_dead_zone(1.5), 1.0);
  PadMapping mapping;
  mapping.next(press(PadButton::A));
  const DriveStep resting = mapping.next(sticks(0.1, 0.1, -0.1));
  EXPECT_FALSE(resting.is_new);  // a stick resting off centre does not start a walk
  EXPECT_EQ(resting.command.mode, 12);
  EXPECT_NEAR(mapping.next(sticks(0.0, 0.575, 0.0)).command.vel_des[0], 0.3, 1e-6);
}

TEST(PadMapping, AReleasedStickStopsTheWalkInsteadOfDrifting) {
  PadMapping mapping;
  mapping.next(press(PadButton::A));
  mapping.next(sticks(0.0, 1.0, 0.0));
  const DriveStep released = mapping.next(sticks(0.05, -0.05, 0.0));
  EXPECT_TRUE(released.is_new);
  EXPECT_EQ(released.command.mode, 11);
  EXPECT_EQ(released.command.vel_des, (std::array<float, 3>{0.0f, 0.0f, 0.0f}));
}

TEST(PadMapping, AnUnchangedPadRepeatsTheCommandAsTheHeartbeat) {
  PadMapping mapping;
  mapping.next(press(PadButton::A));
  mapping.next(sticks(0.0, 0.5, 0.0));
  const DriveStep again = mapping.next(sticks(0.0, 0.5, 0.0));
  EXPECT_FALSE(again.is_new);
  EXPECT_EQ(again.command.mode, 11);
}

TEST(PadMapping, SticksWaitForAButtonWhileLyingOrInAMotion) {
  for (const PadButton before : {PadButton::X, PadButton::B, PadButton::RightShoulder}) {
    PadMapping mapping;
    const int mode = mapping.next(press(before)).command.mode;
    const DriveStep pushed = mapping.next(sticks(0.0, 1.0, 0.0));
    EXPECT_FALSE(pushed.is_new);
    EXPECT_EQ(pushed.command.mode, mode);
  }
}

TEST(PadMapping, YWalksThenCyclesThroughTheWalkingGaitsButNotThePassiveTrot) {
  PadMapping mapping;
  mapping.next(press(PadButton::A));
  EXPECT_EQ(mapping.next(press(PadButton::Y)).command.gait_id, 27);  // the first press walks on
  std::set<int> seen;
  for (int i = 0; i < pad_gait_count(); ++i) seen.insert(mapping.next(press(PadButton::Y)).command.gait_id);
  EXPECT_EQ(seen, (std::set<int>{2, 3, 7, 10, 26, 27}));
  EXPECT_EQ(mapping.gait_id(), 27);  // round again
}

TEST(PadMapping, TheStickScalesToTheRunningGaitsLimits) {
  PadMapping mapping;
  mapping.next(press(PadButton::A));
  mapping.next(press(PadButton::Y));
  while (mapping.gait_id() != 10) mapping.next(press(PadButton::Y));
  const DriveStep flying = mapping.next(sticks(0.0, 1.0, 0.0));
  EXPECT_FLOAT_EQ(flying.command.vel_des[0], 1.6f);  // flying trot: vx up to 1.6, back to -1.2
  EXPECT_FLOAT_EQ(mapping.next(sticks(0.0, -1.0, 0.0)).command.vel_des[0], -1.2f);
}

TEST(PadMapping, StopKeepsTheModeAndZeroesTheVelocity) {
  PadMapping mapping;
  mapping.next(press(PadButton::A));
  mapping.next(sticks(0.3, 1.0, 0.4));
  const DriveStep stop = mapping.stop();
  EXPECT_TRUE(stop.is_new);
  EXPECT_EQ(stop.command.mode, 11);
  EXPECT_EQ(stop.command.gait_id, 27);
  EXPECT_EQ(stop.command.vel_des, (std::array<float, 3>{0.0f, 0.0f, 0.0f}));
}

TEST(PadMapping, TheHelpNamesEveryButtonAndGait) {
  const std::string help = pad_mapping_help();
  for (const ButtonBinding& binding : kButtonBindings) EXPECT_NE(help.find(binding.what), std::string::npos);
  EXPECT_NE(help.find("27 slow trot"), std::string::npos);
  EXPECT_EQ(help.find("walk-dog"), std::string::npos);
}

// docs/driving.md shows the mapping as `cerebellum drive` prints it: the page cannot drift from the code
TEST(PadMapping, DrivingDocsShowTheMappingExactlyAsTheProgramPrintsIt) {
  std::ifstream in(std::filesystem::path(CEREBELLUM_SOURCE_DIR) / "docs" / "driving.md");
  ASSERT_TRUE(in) << "docs/driving.md";
  std::ostringstream page;
  page << in.rdbuf();
  EXPECT_NE(page.str().find(pad_mapping_help()), std::string::npos)
      << "paste the output of `cerebellum drive --help` from 'mapping' on into docs/driving.md:\n"
      << pad_mapping_help();
}

}  // namespace
}  // namespace cerebellum
