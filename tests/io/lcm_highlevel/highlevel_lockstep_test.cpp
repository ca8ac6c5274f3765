// The MC in lockstep (ticks driven by the test) with the high-level adapter, and a raw LCM peer in
// the same network namespace. Before ticking on after a send, the test waits until the adapter's
// thread has handed the packet to the machine, so every command gets a known robot time.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "loop/mc.hpp"
#include "loop/simulated_robot.hpp"
#include "io/lcm_highlevel/big_endian_writer.hpp"
#include "io/lcm_highlevel/raw_lcm_peer.hpp"
#include "io/lcm_highlevel/lcm_highlevel_adapter.hpp"
#include "lowlevel/motor_sdk/motor_sdk_source.hpp"

namespace cerebellum {
namespace {

using test::Bytes;
using test::eventually;

constexpr std::int32_t kMotorHealthyOnWire = static_cast<std::int32_t>(0x80000000u);
// in Off the MC drives no motor: the drivers are in reset (bits 30..31 = 0), no error bits
constexpr std::int32_t kMotorResetOnWire = 0;

Bytes command(int mode, int gait_id, int life_count, std::int32_t duration_ms = 0) {
  return test::robot_control_cmd_packet(static_cast<std::int8_t>(mode), static_cast<std::int8_t>(gait_id), 0x0F,
                                        static_cast<std::int8_t>(life_count), 0.0f, 0, duration_ms);
}

McConfig lockstep_config(double keepalive_s) {
  McConfig config = default_config();
  config.startup = Startup::Off;
  config.highlevel.enabled = true;
  config.highlevel.response_keepalive_s = keepalive_s;
  return config;
}

class HighLevelLockstep : public ::testing::Test {
 protected:
  explicit HighLevelLockstep(double keepalive_s = 0.0)
      : config_(lockstep_config(keepalive_s)),
        log_(std::tmpfile()),
        mc_(make_simulated_mc(config_)),
        adapter_(mc_.client_port(HighLevelSource::CyberDog2Lcm), mc_.user_gait_upload(), config_.highlevel,
                 config_.loop_period_s, log_) {
    mc_.loop().add_observer(adapter_);
  }
  ~HighLevelLockstep() override { std::fclose(log_); }

  // publishes one packet and waits until the adapter has submitted it (or counted it as malformed)
  void send(const Bytes& packet) {
    const std::uint64_t before = handled();
    peer_.publish_command(packet);
    ASSERT_TRUE(eventually([&] { return handled() == before + 1; })) << "the adapter did not take the packet";
  }
  std::uint64_t handled() const {
    const HighLevelInterfaceCounters c = adapter_.counters();
    return c.commands_submitted + c.wrong_fingerprint + c.truncated + c.oversized;
  }

  // ticks, letting the interface thread publish what is due as it goes
  void tick(int ticks) {
    for (int i = 0; i < ticks; ++i) {
      mc_.loop().tick();
      if ((i + 1) % 32 == 0) wait_published();
    }
    wait_published();
  }
  void wait_published() {
    ASSERT_TRUE(eventually([&] {
      const HighLevelInterfaceCounters c = adapter_.counters();
      return c.feedback_sent == c.feedback_queued;
    }));
  }
  // every published response has reached the peer
  void wait_delivered() {
    ASSERT_TRUE(eventually([&] {
      const HighLevelInterfaceCounters c = adapter_.counters();
      return peer_.count("robot_control_response") == c.responses_published &&
             peer_.count("global_to_robot") == c.odometry_published &&
             peer_.count("motor_temperature") == c.temperatures_published;
    }));
  }

  const HighLevelStatus& status() { return mc_.machine().status(); }
  const ClientCounters& machine_counters() { return mc_.machine().counters(); }

  std::string log_text() {
    std::fflush(log_);
    std::rewind(log_);
    std::string text;
    char chunk[512];
    while (std::fgets(chunk, sizeof chunk, log_) != nullptr) text += chunk;
    return text;
  }

  McConfig config_;
  std::FILE* log_;
  Mc mc_;
  LcmHighLevelAdapter adapter_;
  test::RawLcmPeer peer_;
};

TEST_F(HighLevelLockstep, FiftyResponsesPerSimulatedSecond) {
  tick(500);
  HighLevelInterfaceCounters c = adapter_.counters();
  EXPECT_EQ(c.responses_published, 50u);
  EXPECT_EQ(c.odometry_published, 50u);
  EXPECT_EQ(c.temperatures_published, 1u);
  EXPECT_EQ(c.telemetry_dropped, 0u);
  wait_delivered();
  const std::vector<robot_control_response_lcmt> responses = peer_.responses();
  ASSERT_EQ(responses.size(), 50u);
  for (const robot_control_response_lcmt& r : responses) {
    EXPECT_EQ(r.mode, 0);
    EXPECT_EQ(r.order_process_bar, 100);
    EXPECT_EQ(r.switch_status, 0);
  }
  // the first tick's state is not trusted yet, so the guard damps (motor mode); from then on Off
  // drives nothing
  for (std::size_t k = 1; k < responses.size(); ++k) {
    for (std::int32_t word : responses[k].motor_error) EXPECT_EQ(word, kMotorResetOnWire) << k;
  }
  // odometry every 20 ms of robot time
  const std::vector<localization_lcmt> odometry = peer_.odometry();
  ASSERT_EQ(odometry.size(), 50u);
  for (std::size_t i = 1; i < odometry.size(); ++i) {
    EXPECT_NEAR(static_cast<double>(odometry[i].timestamp - odometry[i - 1].timestamp), 20e6, 1e3) << i;
  }
  EXPECT_NEAR(odometry.back().xyz[2], mc_.loop().last_cycle().state.position_world.z(), 0.05);

  tick(1000);
  c = adapter_.counters();
  EXPECT_EQ(c.responses_published, 150u);
  EXPECT_EQ(c.temperatures_published, 3u);
  wait_delivered();
  EXPECT_EQ(peer_.temperatures().size(), 3u);
}

TEST_F(HighLevelLockstep, NewLifeCountIsAppliedRepeatedOneIsAHeartbeat) {
  tick(5);
  send(command(7, 0, 5));
  tick(1);
  EXPECT_EQ(status().mode, 7);
  EXPECT_EQ(machine_counters().new_commands.load(), 1u);

  // same life_count, other content: only a heartbeat
  send(command(0, 0, 5));
  tick(1);
  EXPECT_EQ(status().mode, 7);
  EXPECT_EQ(machine_counters().new_commands.load(), 1u);
  EXPECT_EQ(machine_counters().received.load(), 2u);

  // any change of life_count is new, not only +1
  send(command(0, 0, -100));
  tick(1);
  EXPECT_EQ(status().mode, 0);
  EXPECT_EQ(machine_counters().new_commands.load(), 2u);
}

TEST_F(HighLevelLockstep, CommandsAreStampedWithRobotTime) {
  send(command(12, 0, 1));
  tick(1);
  ASSERT_EQ(status().mode, 12);
  // heartbeats every 0.1 s of robot time keep the client alive
  for (int i = 0; i < 10; ++i) {
    tick(50);
    send(command(12, 0, 1));
  }
  EXPECT_EQ(machine_counters().timeouts.load(), 0u);
  // 0.48 s after the last heartbeat: still alive; 0.52 s: get-down protection
  tick(240);
  EXPECT_EQ(machine_counters().timeouts.load(), 0u);
  EXPECT_EQ(status().mode, 12);
  tick(20);
  EXPECT_EQ(machine_counters().timeouts.load(), 1u);
  EXPECT_EQ(status().mode, 7);
  EXPECT_TRUE(eventually([&] { return log_text().find("no robot_control_cmd for 0.5 s") != std::string::npos; }, 3.0))
      << log_text();
}

TEST_F(HighLevelLockstep, MalformedPacketsAreCountedAndLogged) {
  std::uint64_t truncated = 0;
  std::uint64_t oversized = 0;
  std::uint64_t wrong = 0;
  const Bytes good = command(7, 0, 3);
  send(Bytes{});
  send(Bytes(good.begin(), good.begin() + 3));
  send(Bytes(good.begin(), good.end() - 1));
  truncated += 3;
  Bytes longer = good;
  longer.resize(200, 0xAB);
  send(longer);
  ++oversized;
  Bytes foreign = good;
  foreign[3] ^= 0x10;
  send(foreign);
  ++wrong;
  // seeded noise: short packets are truncated, the rest carry a foreign fingerprint
  std::mt19937 rng(7);
  std::uniform_int_distribution<int> length(0, 300);
  std::uniform_int_distribution<int> byte(0, 255);
  for (int i = 0; i < 40; ++i) {
    Bytes noise(static_cast<std::size_t>(length(rng)));
    for (std::uint8_t& b : noise) b = static_cast<std::uint8_t>(byte(rng));
    if (noise.size() >= 8 && noise[0] == good[0]) noise[0] ^= 0xFF;
    send(noise);
    (noise.size() < 8 ? truncated : wrong) += 1;
  }
  HighLevelInterfaceCounters c = adapter_.counters();
  EXPECT_EQ(c.truncated, truncated);
  EXPECT_EQ(c.oversized, oversized);
  EXPECT_EQ(c.wrong_fingerprint, wrong);
  EXPECT_EQ(c.commands_submitted, 0u);

  // the interface still works, and NaN in a well-formed packet is the machine's to reject
  send(good);
  tick(1);
  EXPECT_EQ(status().mode, 7);
  Bytes nan_packet = command(0, 0, 4);
  const Bytes nan_bits = test::BigEndianWriter().f32(std::nanf("")).bytes();
  std::copy(nan_bits.begin(), nan_bits.end(), nan_packet.begin() + 12);  // vel_des[0]
  send(nan_packet);
  tick(1);
  EXPECT_EQ(machine_counters().rejected_non_finite.load(), 1u);
  EXPECT_EQ(status().mode, 7);
  tick(20);
  EXPECT_EQ(adapter_.counters().responses_published, 3u);  // ticks 0, 10, 20
  EXPECT_TRUE(eventually(
      [&] { return log_text().find("robot_control_cmd packets rejected in the last second") != std::string::npos; },
      3.0))
      << log_text();
}

TEST_F(HighLevelLockstep, NineTimedStepsPushedAtOnceAllRunInOrder) {
  const std::vector<std::pair<int, int>> steps{{7, 0}, {0, 0}, {7, 0}, {0, 0}, {7, 1}, {0, 0}, {7, 0}, {0, 0}, {7, 0}};
  tick(1);
  for (std::size_t i = 0; i < steps.size(); ++i) {
    peer_.publish_command(command(steps[i].first, steps[i].second, static_cast<int>(i) + 1, 100));
  }
  ASSERT_TRUE(eventually([&] { return adapter_.counters().commands_submitted == steps.size(); }));

  std::vector<std::pair<int, int>> seen{{status().mode, status().gait_id}};
  for (int t = 1; t <= 2000; ++t) {
    tick(1);
    const std::pair<int, int> now{status().mode, status().gait_id};
    if (now != seen.back()) seen.push_back(now);
    // the client keeps repeating its last message
    if (t % 50 == 0) send(command(7, 0, 9, 100));
  }
  std::vector<std::pair<int, int>> expected{{0, 0}};
  expected.insert(expected.end(), steps.begin(), steps.end());
  EXPECT_EQ(seen, expected);
  EXPECT_EQ(machine_counters().new_commands.load(), 9u);
  EXPECT_EQ(machine_counters().queue_full.load(), 0u);
  EXPECT_EQ(machine_counters().timeouts.load(), 0u);
  // after the last step PureDamper holds itself: the reference's hold (21, 3) may not follow 7,
  // and a refusal of a command nobody sent would only confuse the client
  EXPECT_EQ(status().mode, 7);
  EXPECT_EQ(status().switch_status, SwitchStatus::Done);
  EXPECT_EQ(machine_counters().banned_transitions.load(), 0u);
  wait_delivered();
  const std::vector<robot_control_response_lcmt> responses = peer_.responses();
  ASSERT_FALSE(responses.empty());
  EXPECT_EQ(responses.back().mode, 7);
  EXPECT_EQ(responses.back().switch_status, 0);
}

TEST_F(HighLevelLockstep, WhileTheMotorSdkHoldsTheRobotResponsesAreLiveAndNewCommandsAreBanned) {
  MotorSdkSource sdk{MotorSdkParameters{}};
  mc_.arbiter().add_low_level_source(sdk);
  tick(250);  // the robot drops and lies in Off
  // a motor SDK client's zero frames latch it (from Off); it keeps sending them
  auto tick_with_sdk = [&](int ticks) {
    for (int i = 0; i < ticks; ++i) {
      ASSERT_EQ(sdk.mailbox().push(JointCommand{}, mc_.loop().last_cycle().state.time_s), PushResult::Accepted);
      tick(1);
    }
  };
  tick_with_sdk(5);
  ASSERT_EQ(mc_.arbiter().latched(), &sdk);
  EXPECT_EQ(status().mode, 15);

  // the robot ends up upside down: the response says so with the live contacts
  mc_.simulation().set_base_pose({0.0, 0.0, 0.3}, {0.0, 1.0, 0.0, 0.0});
  tick_with_sdk(500);
  const RobotState& live = mc_.loop().last_cycle().state;
  int live_contact = 0;
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) live_contact |= live.contact[leg] > 0.5 ? 1 << leg : 0;
  wait_delivered();
  robot_control_response_lcmt response = peer_.responses().back();
  EXPECT_EQ(response.mode, 15);
  EXPECT_EQ(response.ori_error, 1);
  EXPECT_EQ(response.contact, live_contact);
  EXPECT_EQ(response.switch_status, 0);
  for (std::int32_t word : response.motor_error) EXPECT_EQ(word, kMotorHealthyOnWire);

  // a recovery stand is refused at once (BAN_TRANS), counted and logged naming the holder
  send(command(12, 0, 1));
  tick_with_sdk(20);
  EXPECT_EQ(status().mode, 15);
  EXPECT_EQ(machine_counters().banned_transitions.load(), 1u);
  wait_delivered();
  response = peer_.responses().back();
  EXPECT_EQ(response.mode, 15);
  EXPECT_EQ(response.switch_status, 5);
  EXPECT_EQ(mc_.arbiter().latched(), &sdk);
  EXPECT_TRUE(
      eventually([&] { return log_text().find("refused mode 12 gait 0 while in mode 15") != std::string::npos; }, 3.0))
      << log_text();
  EXPECT_NE(log_text().find("the motor SDK"), std::string::npos) << log_text();

  // heartbeats are no refusals, and the machine takes every one of them (no overflow)
  for (int i = 0; i < 200; ++i) {
    send(command(12, 0, 1));
    tick_with_sdk(1);
  }
  EXPECT_EQ(machine_counters().banned_transitions.load(), 1u);
  EXPECT_EQ(machine_counters().received.load(), 201u);
  EXPECT_EQ(mc_.machine().input_counters(HighLevelSource::CyberDog2Lcm).ring_overflow.load(), 0u);
  EXPECT_EQ(machine_counters().timeouts.load(), 0u);
}

TEST_F(HighLevelLockstep, UserGaitFilesAreAnsweredAndStored) {
  peer_.publish_gait_file(test::file_send_packet(
      "# Gait Def\n[[section]]\ncontact = [1, 1, 1, 1]\nduration = 10\n[[section]]\ncontact = [0, 1, 1, 0]\n"
      "duration = 4\n"));
  ASSERT_TRUE(eventually([&] { return peer_.gait_results().size() == 1; }));
  EXPECT_EQ(peer_.gait_results()[0].result, 0);
  ASSERT_TRUE(adapter_.user_gaits().definition().has_value());
  EXPECT_EQ(adapter_.user_gaits().definition()->sections.size(), 2u);

  peer_.publish_gait_file(test::file_send_packet("a shopping list\n"));
  ASSERT_TRUE(eventually([&] { return peer_.gait_results().size() == 2; }));
  EXPECT_EQ(peer_.gait_results()[1].result, 1);

  peer_.publish_gait_file(
      test::file_send_packet("# Gait Params\n[[step]]\nmode = 11\ngait_id = 110\nduration = 300\n"));
  ASSERT_TRUE(eventually([&] { return peer_.gait_results().size() == 3; }));
  EXPECT_EQ(peer_.gait_results()[2].result, 0);
  ASSERT_TRUE(adapter_.user_gaits().parameters().has_value());
  EXPECT_EQ(adapter_.user_gaits().parameters()->steps.at(0).duration, 300);

  peer_.publish_gait_file(command(12, 0, 1));  // not a file_send_lcmt at all
  ASSERT_TRUE(eventually([&] { return peer_.gait_results().size() == 4; }));
  EXPECT_EQ(peer_.gait_results()[3].result, 1);
  EXPECT_EQ(adapter_.counters().gait_files_accepted, 2u);
  EXPECT_EQ(adapter_.counters().gait_files_refused, 2u);
  EXPECT_EQ(adapter_.user_gaits().version(), 2u);
  const std::string log = log_text();
  EXPECT_NE(log.find("user_gait_file refused (result 1): does not begin with '# Gait Def' or '# Gait Params'"),
            std::string::npos)
      << log;
  EXPECT_NE(log.find("user_gait_file refused (result 1): wrong fingerprint packet of 124 bytes"), std::string::npos)
      << log;
  // the fields the MC accepts and does not use are said where the upload is logged, not dropped silently
  EXPECT_NE(log.find("user_gait_file stored (result 0), gait parameters: 1 steps, 300 ms (acc_des (WBC weights) and "
                     "value bit 0 (use_mpc_traj) not used: no WBC here"),
            std::string::npos)
      << log;
}

class HighLevelKeepalive : public HighLevelLockstep {
 protected:
  HighLevelKeepalive() : HighLevelLockstep(0.05) {}
};

TEST_F(HighLevelKeepalive, ResponsesContinueWhileTheLoopTicksSlowlyAndStopWhenItHangs) {
  tick(1);
  // a loop paced far below real time: each new tick is answered by a keepalive response (tick 0
  // was the only scheduled one), however long the tick takes to come
  for (int i = 0; i < 4; ++i) {
    const std::uint64_t before = adapter_.counters().responses_published;
    tick(1);
    ASSERT_TRUE(test::eventually([&] { return adapter_.counters().responses_published > before; }))
        << "no keepalive for tick " << i + 1;
  }
  // a loop that no longer ticks gets no more than the one for its last tick: a window of six
  // keepalive periods in which a keepalive of every period would show
  const std::uint64_t while_ticking = adapter_.counters().responses_published;
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  EXPECT_LE(adapter_.counters().responses_published, while_ticking + 1);
}

}  // namespace
}  // namespace cerebellum
