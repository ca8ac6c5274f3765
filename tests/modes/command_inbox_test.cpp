// The per-source inbox on one thread: order within a source, the per-source share of a call,
// interleaving, the rotating first source, overflow counted per source.
#include "modes/command_inbox.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace cerebellum {
namespace {

constexpr auto kLcm = HighLevelSource::CyberDog2Lcm;
constexpr auto kAlienGo = HighLevelSource::AlienGoUdp;
constexpr auto kKeys = HighLevelSource::ViewerKeyboard;

TimedCommand input(HighLevelSource source, int value) {
  TimedCommand t;
  t.source = source;
  t.command.value = value;
  return t;
}

std::vector<TimedCommand> take_all_once(CommandInbox& inbox) {
  std::vector<TimedCommand> taken;
  inbox.take([&](const TimedCommand& t) { taken.push_back(t); });
  return taken;
}

TEST(CommandInbox, HandsOutEachSourcesCommandsInOrderInterleavedOneEach) {
  CommandInbox inbox;
  for (int i = 0; i < 3; ++i) ASSERT_TRUE(inbox.push(input(kLcm, i)));
  for (int i = 10; i < 12; ++i) ASSERT_TRUE(inbox.push(input(kAlienGo, i)));
  const std::vector<TimedCommand> taken = take_all_once(inbox);
  ASSERT_EQ(taken.size(), 5u);
  const int expected[] = {0, 10, 1, 11, 2};
  for (std::size_t i = 0; i < taken.size(); ++i) EXPECT_EQ(taken[i].command.value, expected[i]) << i;
}

TEST(CommandInbox, TakesAtMostItsShareOfEachSourcePerCallAndTheRestNextCall) {
  CommandInbox inbox;
  const int pushed = static_cast<int>(CommandInbox::kTakePerSourcePerTick) + 5;
  for (int i = 0; i < pushed; ++i) ASSERT_TRUE(inbox.push(input(kAlienGo, i)));
  ASSERT_TRUE(inbox.push(input(kLcm, 100)));
  std::vector<TimedCommand> first = take_all_once(inbox);
  ASSERT_EQ(first.size(), CommandInbox::kTakePerSourcePerTick + 1);
  int aliengo = 0;
  for (const TimedCommand& t : first) aliengo += t.source == kAlienGo ? 1 : 0;
  EXPECT_EQ(aliengo, static_cast<int>(CommandInbox::kTakePerSourcePerTick));
  const std::vector<TimedCommand> second = take_all_once(inbox);
  ASSERT_EQ(second.size(), 5u);
  EXPECT_EQ(second.front().command.value, static_cast<int>(CommandInbox::kTakePerSourcePerTick));
  EXPECT_TRUE(take_all_once(inbox).empty());
  EXPECT_EQ(inbox.counters(kAlienGo).taken.load(), static_cast<std::uint64_t>(pushed));
}

TEST(CommandInbox, TheSourceTakenFirstRotatesFromCallToCall) {
  CommandInbox inbox;
  std::vector<HighLevelSource> firsts;
  for (int call = 0; call < 4; ++call) {
    inbox.push(input(kLcm, call));
    inbox.push(input(kAlienGo, call));
    inbox.push(input(kKeys, call));
    firsts.push_back(take_all_once(inbox).front().source);
  }
  EXPECT_EQ(firsts, (std::vector<HighLevelSource>{kLcm, kAlienGo, kKeys, kLcm}));
}

TEST(CommandInbox, AFullSourceRefusesAndCountsOnlyItsOwnCommands) {
  CommandInbox inbox;
  for (std::size_t i = 0; i < CommandInbox::kRingCapacity; ++i) ASSERT_TRUE(inbox.push(input(kAlienGo, 0)));
  EXPECT_FALSE(inbox.push(input(kAlienGo, 0)));
  EXPECT_EQ(inbox.counters(kAlienGo).ring_overflow.load(), 1u);
  EXPECT_TRUE(inbox.push(input(kLcm, 0))) << "the other client's ring is its own";
  EXPECT_EQ(inbox.counters(kLcm).ring_overflow.load(), 0u);
  EXPECT_EQ(inbox.counters(kAlienGo).submitted.load(), CommandInbox::kRingCapacity);
}

}  // namespace
}  // namespace cerebellum
