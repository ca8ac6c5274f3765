// The command semantics of the reference, tick by tick (2 ms ticks).
#include "modes/command_queue.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace cerebellum {
namespace {

HighLevelCommand cmd(int mode, int gait, int life_count, int duration_ms = 0) {
  HighLevelCommand c;
  c.mode = mode;
  c.gait_id = gait;
  c.life_count = life_count;
  c.duration = duration_ms;
  return c;
}

TEST(CommandQueue, FirstCommandWithLifeCountZeroIsNew) {
  CommandQueue queue(0.002);
  EXPECT_EQ(queue.receive(cmd(12, 0, 0), 0.0), CommandQueue::Receipt::RunsNow);
  ASSERT_NE(queue.current(), nullptr);
  EXPECT_EQ(queue.current()->mode, 12);
}

TEST(CommandQueue, SameLifeCountIsAHeartbeatAndAnyChangeIsNew) {
  CommandQueue queue(0.002);
  queue.receive(cmd(12, 0, 5), 0.0);
  const auto generation = queue.generation();
  EXPECT_EQ(queue.receive(cmd(21, 0, 5), 0.1), CommandQueue::Receipt::Heartbeat);
  EXPECT_EQ(queue.current()->mode, 12);
  EXPECT_EQ(queue.generation(), generation);
  EXPECT_EQ(queue.receive(cmd(21, 0, 3), 0.2), CommandQueue::Receipt::RunsNow);  // not only +1
  EXPECT_EQ(queue.current()->mode, 21);
}

TEST(CommandQueue, HeartbeatsKeepTheClientAliveAndSilenceTimesOutAfterHalfASecond) {
  CommandQueue queue(0.002);
  EXPECT_FALSE(queue.timed_out(10.0));  // no client yet
  queue.receive(cmd(12, 0, 1), 0.0);
  queue.receive(cmd(12, 0, 1), 0.4);
  EXPECT_FALSE(queue.timed_out(0.9));
  EXPECT_TRUE(queue.timed_out(0.902));
}

TEST(CommandQueue, ModeMinusOneIsIgnored) {
  CommandQueue queue(0.002);
  EXPECT_EQ(queue.receive(cmd(-1, 0, 1), 0.0), CommandQueue::Receipt::Ignored);
  EXPECT_EQ(queue.current(), nullptr);
}

TEST(CommandQueue, NonFiniteCommandIsRejectedButCountsAsAliveSignal) {
  CommandQueue queue(0.002);
  HighLevelCommand bad = cmd(11, 27, 1);
  bad.vel_des[0] = std::nanf("");
  EXPECT_EQ(queue.receive(bad, 0.0), CommandQueue::Receipt::Rejected);
  EXPECT_EQ(queue.current(), nullptr);
  EXPECT_FALSE(queue.timed_out(0.3));
  // the same life_count with good values is still new, since the bad one was not taken
  EXPECT_EQ(queue.receive(cmd(11, 27, 1), 0.1), CommandQueue::Receipt::RunsNow);
}

TEST(CommandQueue, TimedEntriesRunForDurationOverTwoTicksThenTheNext) {
  CommandQueue queue(0.002);
  queue.receive(cmd(12, 0, 1, 10), 0.0);  // 5 ticks
  queue.receive(cmd(21, 0, 2, 6), 0.0);   // 3 ticks
  EXPECT_EQ(queue.size(), 2u);
  for (int t = 0; t < 4; ++t) {
    queue.tick(false);
    EXPECT_EQ(queue.current()->mode, 12) << t;
  }
  queue.tick(false);
  EXPECT_EQ(queue.current()->mode, 21);
}

TEST(CommandQueue, TickCounterStandsStillWhileSwitching) {
  CommandQueue queue(0.002);
  queue.receive(cmd(12, 0, 1, 4), 0.0);  // 2 ticks
  queue.receive(cmd(21, 0, 2, 4), 0.0);
  for (int t = 0; t < 10; ++t) queue.tick(true);
  EXPECT_EQ(queue.current()->mode, 12);
  queue.tick(false);
  queue.tick(false);
  EXPECT_EQ(queue.current()->mode, 21);
}

TEST(CommandQueue, HoldCommandFollowsTheLastTimedEntry) {
  struct Case {
    int mode, gait, hold_mode, hold_gait;
  };
  for (const Case c : {Case{3, 0, 3, 1}, Case{11, 27, 11, 1}, Case{11, 110, 11, 31}, Case{12, 0, 21, 3},
                       Case{21, 5, 21, 3}, Case{62, 2, 21, 3},
                       // 7 -> 21 is not allowed: PureDamper holds itself instead of a refused pose hold
                       Case{7, 1, 7, 1}}) {
    CommandQueue queue(0.002);
    HighLevelCommand timed = cmd(c.mode, c.gait, 1, 2);
    timed.vel_des = {0.5f, 0.1f, 0.2f};
    queue.receive(timed, 0.0);
    queue.tick(false);
    ASSERT_NE(queue.current(), nullptr);
    EXPECT_EQ(queue.current()->mode, c.hold_mode) << c.mode;
    EXPECT_EQ(queue.current()->gait_id, c.hold_gait) << c.mode;
    EXPECT_EQ(queue.current()->vel_des[0], 0.0f);
    EXPECT_EQ(queue.current()->duration, 0);
  }
}

TEST(CommandQueue, DurationZeroClearsTheQueueAndTimedEntriesDropLeadingEndlessOnes) {
  CommandQueue queue(0.002);
  queue.receive(cmd(12, 0, 1, 100), 0.0);
  queue.receive(cmd(21, 0, 2, 100), 0.0);
  EXPECT_EQ(queue.receive(cmd(7, 0, 3, 0), 0.0), CommandQueue::Receipt::RunsNow);
  EXPECT_EQ(queue.size(), 1u);
  EXPECT_EQ(queue.receive(cmd(12, 0, 4, 100), 0.0), CommandQueue::Receipt::Queued);
  EXPECT_EQ(queue.size(), 1u);
  EXPECT_EQ(queue.current()->mode, 12);
}

TEST(CommandQueue, NineStepSequencePushedAtOnceRunsStepByStep) {
  CommandQueue queue(0.002);
  const int durations_ms[9] = {100, 200, 300, 400, 500, 600, 700, 800, 900};
  for (int i = 0; i < 9; ++i) queue.receive(cmd(21, 0, i + 1, durations_ms[i]), 0.01 * i);
  EXPECT_EQ(queue.size(), 9u);
  int ticks = 0;
  for (int i = 0; i < 9; ++i) {
    ASSERT_EQ(queue.current()->life_count, i + 1);
    int step_ticks = 0;
    while (queue.current()->life_count == i + 1 && queue.current()->duration != 0) {
      queue.tick(false);
      ++step_ticks;
    }
    EXPECT_EQ(step_ticks, durations_ms[i] / 2) << "step " << i;
    ticks += step_ticks;
  }
  EXPECT_EQ(ticks, 4500 / 2);
  EXPECT_EQ(queue.current()->gait_id, 3);  // hold pose
}

TEST(CommandQueue, FullQueueRefusesMoreTimedEntries) {
  CommandQueue queue(0.002);
  for (int i = 0; i < static_cast<int>(CommandQueue::kCapacity); ++i) {
    EXPECT_EQ(queue.receive(cmd(21, 0, i % 100, 100), 0.0), CommandQueue::Receipt::Queued);
  }
  EXPECT_EQ(queue.receive(cmd(21, 0, 100, 100), 0.0), CommandQueue::Receipt::QueueFull);
}

TEST(CommandQueue, AWithdrawnCommandLeavesTheQueueAsItWasBeforeItArrived) {
  CommandQueue queue(0.002);
  queue.receive(cmd(11, 10, 1, 0), 0.0);  // trotting, until replaced
  const std::uint64_t trotting = queue.generation();
  // a timed entry drops the endless trot in front of it; withdrawn, the trot is back unchanged
  queue.receive(cmd(64, 0, 2, 2000), 0.0);
  ASSERT_EQ(queue.current()->mode, 64);
  queue.withdraw_current();
  ASSERT_NE(queue.current(), nullptr);
  EXPECT_EQ(queue.current()->mode, 11);
  EXPECT_EQ(queue.current()->gait_id, 10);
  EXPECT_EQ(queue.size(), 1u);
  EXPECT_NE(queue.generation(), trotting);  // the machine notes it has nothing new to apply
  const std::uint64_t after = queue.generation();
  for (int i = 0; i < 2000; ++i) queue.tick(false);  // no hold of the withdrawn entry ever comes
  EXPECT_EQ(queue.current()->mode, 11);
  EXPECT_EQ(queue.generation(), after);
  // a duration-0 command that replaced a timed sequence brings the sequence back
  queue.receive(cmd(21, 0, 3, 1000), 0.0);
  queue.receive(cmd(21, 5, 4, 1000), 0.0);
  queue.receive(cmd(64, 0, 5, 0), 0.0);
  ASSERT_EQ(queue.size(), 1u);
  queue.withdraw_current();
  ASSERT_EQ(queue.size(), 2u);
  EXPECT_EQ(queue.current()->gait_id, 0);
}

TEST(CommandQueue, AWithdrawnEntryThatCameUpInTurnGivesWayToTheNextOrToTheHoldBeforeIt) {
  CommandQueue queue(0.002);
  queue.receive(cmd(21, 0, 1, 4), 0.0);
  queue.receive(cmd(64, 0, 2, 4), 0.0);
  queue.receive(cmd(21, 5, 3, 4), 0.0);
  queue.tick(false);
  queue.tick(false);  // 21/0 ran out: 64 is current
  ASSERT_EQ(queue.current()->mode, 64);
  const std::uint64_t before = queue.generation();
  queue.withdraw_current();
  EXPECT_NE(queue.generation(), before);
  EXPECT_EQ(queue.current()->mode, 21);
  EXPECT_EQ(queue.current()->gait_id, 5);
  queue.tick(false);
  queue.tick(false);
  queue.receive(cmd(16, 0, 4, 4), 0.0);  // arrives behind the hold of 21/5: replaces it
  EXPECT_EQ(queue.current()->mode, 16);
  queue.tick(false);
  queue.tick(false);
  // the jump's hold came up in turn; withdrawn, the queue falls back to the hold of 21/5 before it
  ASSERT_EQ(queue.current()->mode, 21);
  EXPECT_EQ(queue.current()->gait_id, 3);
}

}  // namespace
}  // namespace cerebellum
