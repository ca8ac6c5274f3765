// The in-process driver (teleop/port_driver) on a real ClientPort: what reaches the machine's ring,
// with which life_count and when, in robot time.
#include "teleop/port_driver.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "modes/client_book.hpp"

namespace cerebellum {
namespace {

constexpr HighLevelSource kKeys = HighLevelSource::ViewerKeyboard;

PadState press(PadButton button) {
  PadState pad;
  pad.pressed[static_cast<std::size_t>(button)] = true;
  return pad;
}

struct Port {
  ClientBook book;
  CommandInbox inbox;
  PortDriver driver{book.port(kKeys, inbox)};

  // what the tick would take now
  std::vector<TimedCommand> taken() {
    std::vector<TimedCommand> out;
    inbox.take([&](const TimedCommand& input) { out.push_back(input); });
    return out;
  }
};

TEST(PortDriver, NothingReachesTheMachineBeforeTheFirstButton) {
  Port port;
  PadState forward;
  forward.left_y = 1.0;
  for (int i = 0; i < 10; ++i) port.driver.drive(forward, false, 0.05 * i);
  EXPECT_TRUE(port.taken().empty());
  EXPECT_FALSE(port.driver.current().has_value());
}

TEST(PortDriver, AButtonIsSentAtOnceWithANewLifeCountAndTheViewersSource) {
  Port port;
  port.driver.drive({}, false, 0.0);
  port.driver.drive(press(PadButton::A), true, 0.01);
  const std::vector<TimedCommand> sent = port.taken();
  ASSERT_EQ(sent.size(), 1u);
  EXPECT_EQ(sent[0].command.mode, static_cast<int>(ModeId::RecoveryStand));
  EXPECT_EQ(sent[0].source, kKeys);
  EXPECT_DOUBLE_EQ(sent[0].received_s, 0.01);
  const int first_life = sent[0].command.life_count;
  port.driver.drive(press(PadButton::A), true, 0.02);  // the same button again: a new command
  const std::vector<TimedCommand> again = port.taken();
  ASSERT_EQ(again.size(), 1u);
  EXPECT_NE(again[0].command.life_count, first_life);
}

TEST(PortDriver, TheRunningCommandIsRepeatedAsTheHeartbeatEveryTenthOfASecondOfRobotTime) {
  Port port;
  port.driver.drive(press(PadButton::X), true, 1.0);
  ASSERT_EQ(port.taken().size(), 1u);
  std::vector<TimedCommand> beats;
  // 2 s of 60 Hz frames
  for (int frame = 1; frame <= 120; ++frame) {
    port.driver.drive({}, false, 1.0 + frame / 60.0);
    for (const TimedCommand& c : port.taken()) beats.push_back(c);
  }
  ASSERT_GE(beats.size(), 19u);
  ASSERT_LE(beats.size(), 21u);
  for (const TimedCommand& beat : beats) {
    EXPECT_EQ(beat.command.mode, static_cast<int>(ModeId::PureDamper));
    EXPECT_EQ(beat.command.life_count, beats.front().command.life_count) << "a heartbeat repeats the life_count";
  }
  for (std::size_t i = 1; i < beats.size(); ++i) {
    EXPECT_LE(beats[i].received_s - beats[i - 1].received_s, kClientHeartbeatPeriodS + 1.0 / 60.0 + 1e-9);
  }
}

TEST(PortDriver, WhileTheRobotsTimeStandsStillNothingMoreIsSent) {
  Port port;
  port.driver.drive(press(PadButton::A), true, 2.0);
  ASSERT_EQ(port.taken().size(), 1u);
  for (int frame = 0; frame < 100; ++frame) port.driver.drive({}, false, 2.0);  // paused
  EXPECT_TRUE(port.taken().empty());
}

TEST(PortDriver, StopSendsTheZeroVelocityOnceAndThenNoHeartbeat) {
  Port port;
  port.driver.drive(press(PadButton::Y), true, 0.0);  // walk
  PadState forward;
  forward.left_y = 1.0;
  port.driver.drive(forward, false, 0.2);
  std::vector<TimedCommand> sent = port.taken();
  ASSERT_FALSE(sent.empty());
  EXPECT_GT(sent.back().command.vel_des[0], 0.1f);
  port.driver.stop(0.3);
  sent = port.taken();
  ASSERT_EQ(sent.size(), 1u);
  EXPECT_EQ(sent[0].command.mode, static_cast<int>(ModeId::Locomotion));
  EXPECT_EQ(sent[0].command.vel_des[0], 0.0f);
  for (int frame = 0; frame < 60; ++frame) port.driver.drive(forward, false, 0.4 + frame * 0.05);
  EXPECT_TRUE(port.taken().empty());
}

}  // namespace
}  // namespace cerebellum
