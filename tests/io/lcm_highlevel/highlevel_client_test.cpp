// The client library against a scripted peer (exact messages), and against the MC running paced.
#include <cerebellum/highlevel_client.hpp>

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <thread>

#include "loop/mc.hpp"
#include "loop/simulated_robot.hpp"
#include "io/lcm_highlevel/raw_lcm_peer.hpp"
#include "io/lcm_highlevel/lcm_highlevel_adapter.hpp"

namespace cerebellum {
namespace {

using std::chrono::milliseconds;
using test::eventually;

robot_control_cmd_lcmt command_of(int mode, int gait_id) {
  robot_control_cmd_lcmt c{};
  c.mode = static_cast<std::int8_t>(mode);
  c.gait_id = static_cast<std::int8_t>(gait_id);
  c.life_count = 99;  // the client chooses its own
  return c;
}

robot_control_response_lcmt response_of(int mode, int gait_id, int bar, int switch_status = 0) {
  robot_control_response_lcmt r{};
  r.mode = static_cast<std::int8_t>(mode);
  r.gait_id = static_cast<std::int8_t>(gait_id);
  r.order_process_bar = static_cast<std::int8_t>(bar);
  r.switch_status = static_cast<std::int8_t>(switch_status);
  return r;
}

class HighLevelClientScripted : public ::testing::Test {
 protected:
  void SetUp() override { ASSERT_EQ(client_.start(), HighLevelClientStatus::Ok) << client_.last_error(); }

  // publishes a response and waits until the client has it
  void respond(const robot_control_response_lcmt& r) {
    const std::uint64_t before = client_.responses_received();
    peer_.publish_response(r);
    ASSERT_TRUE(eventually([&] { return client_.responses_received() == before + 1; }));
  }

  test::RawLcmPeer peer_;
  HighLevelClient client_;
};

TEST_F(HighLevelClientScripted, FirstSendSyncsLifeCountThenHeartbeatsAtTenHertzOrMore) {
  ASSERT_EQ(client_.send(command_of(12, 0)), HighLevelClientStatus::Ok);
  EXPECT_EQ(client_.life_count(), 1);
  ASSERT_TRUE(eventually([&] { return peer_.commands().size() >= 12; }, 5.0));
  const std::vector<robot_control_cmd_lcmt> sent = peer_.commands();
  // a mode -1 message with the life_count before, then the command, then the same again
  EXPECT_EQ(sent[0].mode, -1);
  EXPECT_EQ(sent[0].life_count, 0);
  for (std::size_t i = 1; i < sent.size(); ++i) {
    EXPECT_EQ(sent[i].mode, 12) << i;
    EXPECT_EQ(sent[i].life_count, 1) << i;
  }
  // the heartbeat's pace is the client's option (checked against the 10 Hz minimum by
  // RejectsHeartbeatsSlowerThanTenHertz), not a wall-clock measurement that a loaded machine skews
  EXPECT_LE(HighLevelClientOptions{}.heartbeat_period, milliseconds(100));

  ASSERT_EQ(client_.send(command_of(7, 1)), HighLevelClientStatus::Ok);
  ASSERT_TRUE(eventually([&] {
    const auto all = peer_.commands();
    return all.back().mode == 7;
  }));
  const std::vector<robot_control_cmd_lcmt> after = peer_.commands();
  EXPECT_EQ(after.back().life_count, 2);
  EXPECT_EQ(after.back().gait_id, 1);
  int syncs = 0;
  for (const robot_control_cmd_lcmt& c : after) syncs += c.mode == -1;
  EXPECT_EQ(syncs, 1);
}

TEST_F(HighLevelClientScripted, LifeCountWrapsLikeAnInt8) {
  for (int i = 0; i < 127; ++i) ASSERT_EQ(client_.send(command_of(12, 0)), HighLevelClientStatus::Ok);
  EXPECT_EQ(client_.life_count(), 127);
  ASSERT_EQ(client_.send(command_of(12, 0)), HighLevelClientStatus::Ok);
  EXPECT_EQ(client_.life_count(), -128);
}

TEST_F(HighLevelClientScripted, WaitForModeNeedsModeGaitAndProgress) {
  ASSERT_EQ(client_.send(command_of(12, 0)), HighLevelClientStatus::Ok);
  EXPECT_EQ(client_.wait_for_mode(12, 0, milliseconds(50)), HighLevelClientStatus::Timeout);  // nothing yet
  respond(response_of(12, 0, 94, 1));
  EXPECT_EQ(client_.wait_for_mode(12, 0, milliseconds(50)), HighLevelClientStatus::Timeout);
  respond(response_of(12, 0, 95, 0));
  EXPECT_EQ(client_.wait_for_mode(12, 0, milliseconds(50)), HighLevelClientStatus::Ok);
  EXPECT_EQ(client_.wait_for_mode(12, std::nullopt, milliseconds(50)), HighLevelClientStatus::Ok);
  EXPECT_EQ(client_.wait_for_mode(12, 17, milliseconds(50)), HighLevelClientStatus::Timeout);
  EXPECT_EQ(client_.wait_for_mode(7, std::nullopt, milliseconds(50)), HighLevelClientStatus::Timeout);
}

TEST_F(HighLevelClientScripted, RefusedOnlyWhenBanTransOutlastsTheSend) {
  respond(response_of(12, 0, 100, 5));  // an old refusal
  ASSERT_EQ(client_.send(command_of(21, 0)), HighLevelClientStatus::Ok);
  respond(response_of(12, 0, 100, 5));
  respond(response_of(12, 0, 100, 5));
  EXPECT_EQ(client_.wait_for_mode(21, 0, milliseconds(50)), HighLevelClientStatus::Timeout);
  respond(response_of(12, 0, 100, 5));
  EXPECT_EQ(client_.wait_for_mode(21, 0, milliseconds(50)), HighLevelClientStatus::Refused);
  // a new send starts counting again
  ASSERT_EQ(client_.send(command_of(21, 0)), HighLevelClientStatus::Ok);
  EXPECT_EQ(client_.wait_for_mode(21, 0, milliseconds(50)), HighLevelClientStatus::Timeout);
}

TEST_F(HighLevelClientScripted, LatestOdometryAndTemperature) {
  EXPECT_FALSE(client_.latest_odometry().has_value());
  EXPECT_FALSE(client_.latest_temperature().has_value());
  localization_lcmt odometry{};
  odometry.xyz[2] = 0.25f;
  odometry.timestamp = 123456789;
  peer_.publish_odometry(odometry);
  danger_states_lcmt temperature{};
  temperature.motor_temperature[11] = 41.5f;
  peer_.publish_temperature(temperature);
  ASSERT_TRUE(eventually([&] { return client_.latest_odometry() && client_.latest_temperature(); }));
  EXPECT_EQ(client_.latest_odometry()->xyz[2], 0.25f);
  EXPECT_EQ(client_.latest_odometry()->timestamp, 123456789);
  EXPECT_EQ(client_.latest_temperature()->motor_temperature[11], 41.5f);
}

TEST_F(HighLevelClientScripted, StoppedClientSendsNothing) {
  ASSERT_EQ(client_.send(command_of(12, 0)), HighLevelClientStatus::Ok);
  ASSERT_TRUE(eventually([&] { return peer_.commands().size() >= 2; }));
  client_.stop();
  client_.stop();
  EXPECT_EQ(client_.send(command_of(7, 0)), HighLevelClientStatus::NotRunning);
  EXPECT_EQ(client_.wait_for_mode(12, 0, milliseconds(10)), HighLevelClientStatus::NotRunning);
  // what was already on its way has arrived once a packet sent after it has (one host, in order)
  const auto flushed_count = [&] {
    const std::size_t markers = peer_.markers_seen();
    peer_.publish_marker();
    EXPECT_TRUE(eventually([&] { return peer_.markers_seen() > markers; }));
    return peer_.commands().size();
  };
  const std::size_t count = flushed_count();
  // a window of three heartbeat periods in which a running client would send: nothing came
  std::this_thread::sleep_for(milliseconds(150));
  EXPECT_EQ(flushed_count(), count);
}

TEST(HighLevelClient, RejectsHeartbeatsSlowerThanTenHertz) {
  HighLevelClientOptions options;
  options.heartbeat_period = milliseconds(150);
  HighLevelClient slow(options);
  EXPECT_EQ(slow.start(), HighLevelClientStatus::InvalidArgument);
  EXPECT_NE(slow.last_error().find("(0, 100] ms"), std::string::npos);
  EXPECT_EQ(slow.send(command_of(12, 0)), HighLevelClientStatus::NotRunning);
  options.heartbeat_period = milliseconds(0);
  EXPECT_EQ(HighLevelClient(options).start(), HighLevelClientStatus::InvalidArgument);
}

TEST(HighLevelClient, ReportsAnUnusableUrl) {
  HighLevelClientOptions options;
  options.response_url = "udpm://not-an-address:7670";
  HighLevelClient client(options);
  EXPECT_EQ(client.start(), HighLevelClientStatus::TransportError);
  EXPECT_NE(client.last_error().find("udpm://not-an-address:7670"), std::string::npos);
}

// the whole path: client -> LCM -> adapter -> machine -> robot -> response -> client, paced at 1x
TEST(HighLevelClientWithMc, StandsRefusesWhatIsMissingAndLiesDown) {
  McConfig config = default_config();
  config.startup = Startup::Off;
  config.highlevel.enabled = true;
  std::FILE* log = std::tmpfile();
  Mc mc = make_simulated_mc(config);
  LcmHighLevelAdapter adapter(mc.client_port(HighLevelSource::CyberDog2Lcm), mc.user_gait_upload(), config.highlevel,
                              config.loop_period_s, log);
  mc.loop().add_observer(adapter);
  std::atomic<bool> stop{false};
  std::thread loop([&] { mc.loop().run({30.0, 1.0}, stop); });

  HighLevelClient client;
  ASSERT_EQ(client.start(), HighLevelClientStatus::Ok);
  ASSERT_EQ(client.send(command_of(12, 0)), HighLevelClientStatus::Ok);
  EXPECT_EQ(client.wait_for_mode(12, 0, milliseconds(10000)), HighLevelClientStatus::Ok);
  ASSERT_TRUE(client.latest_odometry().has_value());
  EXPECT_GT(client.latest_odometry()->xyz[2], 0.2f);  // standing

  robot_control_cmd_lcmt head_up = command_of(21, 0);
  head_up.rpy_des[1] = 0.3f;
  head_up.duration = 500;
  ASSERT_EQ(client.send(head_up), HighLevelClientStatus::Ok);
  const HighLevelClientStatus pose = client.wait_for_mode(21, 0, milliseconds(3000));
  // pose control belongs to another part of the MC: refused until it exists, then reached
  EXPECT_TRUE(pose == HighLevelClientStatus::Refused || pose == HighLevelClientStatus::Ok) << to_string(pose);

  ASSERT_EQ(client.send(command_of(7, 1)), HighLevelClientStatus::Ok);
  EXPECT_EQ(client.wait_for_mode(7, 1, milliseconds(10000)), HighLevelClientStatus::Ok);
  client.stop();
  stop.store(true);
  loop.join();
  EXPECT_EQ(adapter.counters().telemetry_dropped, 0u);
  std::fclose(log);
}

}  // namespace
}  // namespace cerebellum
