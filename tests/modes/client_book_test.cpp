// Each client's counters and refusal notes, and the port its transport is given.
#include "modes/client_book.hpp"

#include <gtest/gtest.h>

#include "scripted_machine.hpp"

namespace cerebellum {
namespace {

using testing::cmd;
constexpr HighLevelSource kLcm = HighLevelSource::CyberDog2Lcm;
constexpr HighLevelSource kAlienGo = HighLevelSource::AlienGoUdp;

TEST(ClientBook, ARefusalIsCountedAndNotedForItsOwnClientOnly) {
  ClientBook book;
  CommandInbox inbox;
  ClientPort lcm = book.port(kLcm, inbox);
  ClientPort aliengo = book.port(kAlienGo, inbox);
  book.refused(kAlienGo, {11, 3, 12, "transition not allowed from the current mode", nullptr});
  EXPECT_EQ(aliengo.counters().banned_transitions.load(), 1u);
  EXPECT_EQ(lcm.counters().banned_transitions.load(), 0u);
  EXPECT_FALSE(lcm.next_note().has_value());
  const std::optional<ClientNote> note = aliengo.next_note();
  ASSERT_TRUE(note.has_value());
  EXPECT_EQ(note->mode, 11);
  EXPECT_EQ(note->from_mode, 12);
  EXPECT_FALSE(aliengo.next_note().has_value());
}

TEST(ClientBook, ACommandRefusedForNotHoldingTheRobotIsNotedOncePerNewCommandButAlwaysCounted) {
  ClientBook book;
  CommandInbox inbox;
  ClientPort port = book.port(kAlienGo, inbox);
  for (int i = 0; i < 5; ++i) book.refused_not_holder(kAlienGo, cmd(ModeId::Locomotion, 3, 1), 12, kLcm);
  book.refused_not_holder(kAlienGo, cmd(ModeId::Locomotion, 3, 2), 12, kLcm);
  EXPECT_EQ(port.counters().refused_not_holder.load(), 6u);
  std::size_t notes = 0;
  while (const std::optional<ClientNote> note = port.next_note()) {
    ++notes;
    EXPECT_STREQ(note->holder, source_name(kLcm));
  }
  EXPECT_EQ(notes, 2u) << "one for life_count 1, one for 2";
}

TEST(ClientBook, APortHandsItsCommandsToItsOwnRingStampedWithItsClient) {
  ClientBook book;
  CommandInbox inbox;
  ClientPort port = book.port(kAlienGo, inbox);
  ASSERT_TRUE(port.submit(cmd(ModeId::RecoveryStand, 0, 4), 1.25));
  std::vector<TimedCommand> taken;
  inbox.take([&](const TimedCommand& input) { taken.push_back(input); });
  ASSERT_EQ(taken.size(), 1u);
  EXPECT_EQ(taken[0].source, kAlienGo);
  EXPECT_EQ(taken[0].received_s, 1.25);
  EXPECT_EQ(taken[0].command.life_count, 4);
  EXPECT_EQ(port.input_counters().submitted.load(), 1u);
  EXPECT_EQ(inbox.counters(kLcm).submitted.load(), 0u);
}

}  // namespace
}  // namespace cerebellum
