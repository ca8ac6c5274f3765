// Two high-level clients on two real threads flooding the machine while the loop thread ticks
// (the defects a flood of both interfaces found: a loop hung draining a torn ring for good,
// commands lost and credited to the wrong client, one client's flood starving the other's
// heartbeats). Judged by counting: every command a producer handed over is taken exactly once and
// credited to its own client, no tick takes more than the fixed input budget, and a well-behaved
// client keeps the robot through another client's flood. The ThreadSanitizer stage runs these.
#include <gtest/gtest.h>

#include <atomic>
#include <cstdint>
#include <thread>

#include "modes/scripted_machine.hpp"

namespace cerebellum {
namespace {

using testing::cmd;
using testing::Machine;

constexpr auto kLcm = HighLevelSource::CyberDog2Lcm;
constexpr auto kAlienGo = HighLevelSource::AlienGoUdp;

std::uint64_t taken_in_total(const HighLevelMachine& machine) {
  return machine.input_counters(kLcm).taken.load() + machine.input_counters(kAlienGo).taken.load();
}

// a client thread: hands over `count` commands stamped time_s, each one again until it is taken
// (a full ring refuses it)
std::thread client(HighLevelMachine& machine, HighLevelSource source, ModeId mode, std::uint64_t count, double time_s) {
  return std::thread([&machine, source, mode, count, time_s] {
    for (std::uint64_t i = 0; i < count; ++i) {
      // a new life_count every 16 commands: new commands and heartbeats mixed, as clients send
      const HighLevelCommand command = cmd(mode, 0, static_cast<int>((i / 16) % 128));
      while (!machine.submit(command, time_s, source)) std::this_thread::yield();
    }
  });
}

TEST(HighLevelMachineFlood, TwoClientThreadsFloodingAtOnceLoseNothingAreCreditedToThemselvesAndNeverHoldATick) {
  Machine m(ModeId::RecoveryStand);
  m.tick();
  const std::uint64_t received_before = m.machine.counters().received.load();
  constexpr std::uint64_t kEach = 200000;
  // the LCM client speaks first and holds the robot; the AlienGo client starts once it does, and
  // each of its commands is refused
  std::thread lcm = client(m.machine, kLcm, ModeId::RecoveryStand, kEach, m.state.time_s);
  JointCommand ignored;
  while (!m.machine.holder()) m.machine.compute(m.state, ignored);
  ASSERT_EQ(m.machine.holder(), kLcm);
  std::thread aliengo = client(m.machine, kAlienGo, ModeId::PureDamper, kEach, m.state.time_s);
  std::uint64_t most_in_a_tick = 0;
  // ticks until both clients' commands are all taken; the robot time stands still, so however the
  // threads are scheduled the holder keeps its lease and no heartbeat times out: what is judged
  // is only whether each command arrives once, whole, from its own client
  for (std::uint64_t taken = taken_in_total(m.machine); taken < 2 * kEach;) {
    m.machine.compute(m.state, ignored);
    const std::uint64_t now = taken_in_total(m.machine);
    most_in_a_tick = std::max(most_in_a_tick, now - taken);
    taken = now;
  }
  lcm.join();
  aliengo.join();
  m.tick();

  EXPECT_LE(most_in_a_tick, CommandInbox::kTakeBudgetPerTick);
  EXPECT_EQ(m.machine.input_counters(kLcm).taken.load(), kEach) << "every LCM command taken once";
  EXPECT_EQ(m.machine.input_counters(kAlienGo).taken.load(), kEach) << "every AlienGo command taken once";
  EXPECT_EQ(m.machine.counters().received.load() - received_before, kEach) << "the holder's commands, all of them";
  EXPECT_EQ(m.machine.counters(kAlienGo).refused_not_holder.load(), kEach)
      << "the other client's commands, each refused as its own";
  EXPECT_EQ(m.machine.counters(kLcm).refused_not_holder.load(), 0u);
  EXPECT_EQ(m.machine.counters(HighLevelSource::CyberDog2Lcm).timeouts.load() +
                m.machine.counters(HighLevelSource::AlienGoUdp).timeouts.load(),
            0u);
  EXPECT_EQ(m.machine.status().mode, static_cast<int>(ModeId::RecoveryStand)) << "no AlienGo command ever ran";
  EXPECT_EQ(m.damper.entered, 0);
}

TEST(HighLevelMachineFlood, AClientFloodingFromItsThreadCostsOnlyItselfTheHoldersHeartbeatsAllArrive) {
  Machine m(ModeId::RecoveryStand);
  m.tick();
  // the well-behaved LCM client (this thread) holds the robot before the flood begins
  ASSERT_TRUE(m.machine.submit(cmd(ModeId::RecoveryStand, 0, 1), m.state.time_s, kLcm));
  m.tick();
  ASSERT_EQ(m.machine.holder(), kLcm);
  std::atomic<bool> flooding{true};
  std::atomic<double> robot_time_s{m.state.time_s};
  // the flooder never waits: whatever its ring cannot hold is dropped and counted as its own
  std::thread flood([&] {
    const HighLevelCommand lie = cmd(ModeId::PureDamper, 0, 1);
    while (flooding.load()) m.machine.submit(lie, robot_time_s.load(), kAlienGo);
  });
  // the LCM client: stand, then walk, a heartbeat every 0.1 s, for 5 s
  int heartbeats_refused = 0;
  for (int tick = 0; tick < 2500; ++tick) {
    if (tick % 50 == 0) {
      // each heartbeat meets a flood that has just overfilled its ring
      const std::uint64_t overflow = m.machine.input_counters(kAlienGo).ring_overflow.load();
      while (m.machine.input_counters(kAlienGo).ring_overflow.load() == overflow) std::this_thread::yield();
      const HighLevelCommand c = tick < 500 ? cmd(ModeId::RecoveryStand, 0, 1) : cmd(ModeId::Locomotion, 3, 2);
      if (!m.machine.submit(c, m.state.time_s, kLcm)) ++heartbeats_refused;
    }
    m.tick();
    robot_time_s.store(m.state.time_s);
  }
  flooding.store(false);
  flood.join();

  EXPECT_EQ(heartbeats_refused, 0);
  EXPECT_EQ(m.machine.input_counters(kLcm).ring_overflow.load(), 0u);
  EXPECT_GT(m.machine.input_counters(kAlienGo).submitted.load(), 0u) << "the flood reached the machine";
  EXPECT_EQ(m.machine.holder(), kLcm);
  EXPECT_EQ(m.machine.counters(HighLevelSource::CyberDog2Lcm).timeouts.load(), 0u)
      << "the holder was never judged silent";
  EXPECT_EQ(m.machine.status().mode, static_cast<int>(ModeId::Locomotion));
  EXPECT_EQ(m.damper.entered, 0) << "the flood never laid the robot down";
}

TEST(HighLevelMachineFlood, ASecondThreadHandingOverForTheSameClientIsRefusedAndCounted) {
  Machine m(ModeId::RecoveryStand);
  ASSERT_TRUE(m.machine.submit(cmd(ModeId::RecoveryStand, 0, 1), m.state.time_s, kLcm));
  bool accepted = true;
  std::thread other([&] { accepted = m.machine.submit(cmd(ModeId::PureDamper, 0, 2), 0.0, kLcm); });
  other.join();
  EXPECT_FALSE(accepted);
  EXPECT_EQ(m.machine.input_counters(kLcm).wrong_thread.load(), 1u);
  EXPECT_EQ(m.machine.input_counters(kLcm).submitted.load(), 1u);
  // another client from that thread is its own source: accepted
  std::thread aliengo([&] { accepted = m.machine.submit(cmd(ModeId::PureDamper, 0, 2), 0.0, kAlienGo); });
  aliengo.join();
  EXPECT_TRUE(accepted);
}

}  // namespace
}  // namespace cerebellum
