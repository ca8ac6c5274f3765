// The simulation's control channel with the MC in lockstep and a raw LCM peer in the same private
// network namespace: a push command moves the standing robot (judged on the simulation's ground
// truth), each command is answered, and malformed packets are counted without an answer.
#include <gtest/gtest.h>
#include <lcm/lcm-cpp.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>
#include <thread>
#include <vector>

#include "loop/mc.hpp"
#include "loop/simulated_robot.hpp"
#include "io/common/eventually.hpp"
#include "io/lcm_sim_control/sim_control_adapter.hpp"
#include "sim_command_lcmt.hpp"
#include "sim_command_result_lcmt.hpp"

namespace cerebellum {
namespace {

class SimControlLockstep : public ::testing::Test {
 protected:
  SimControlLockstep()
      : mc_(make_simulated_mc(config_)),
        log_(std::tmpfile()),
        adapter_(&mc_.simulation(), mc_.faults(), &links_, config_.highlevel.odometry_url, log_),
        peer_(config_.highlevel.odometry_url) {
    peer_.subscribe(kSimCommandResultChannel, &SimControlLockstep::on_result, this);
  }
  ~SimControlLockstep() override {
    adapter_.finish(log_);
    std::fclose(log_);
  }

  void run_for(double seconds) {
    const int ticks = static_cast<int>(std::lround(seconds / config_.loop_period_s));
    for (int i = 0; i < ticks; ++i) mc_.loop().tick();
  }
  // the largest |y - y0| of the trunk over the next `seconds`
  double largest_sideways_shift_m(double y0_m, double seconds) {
    double largest_m = 0.0;
    const int ticks = static_cast<int>(std::lround(seconds / config_.loop_period_s));
    for (int i = 0; i < ticks; ++i) {
      mc_.loop().tick();
      largest_m = std::max(largest_m, std::abs(mc_.simulation().ground_truth().position[1] - y0_m));
    }
    return largest_m;
  }
  void send(std::int64_t id, const std::string& text) {
    sim_command_lcmt command;
    command.request_id = id;
    command.command = text;
    peer_.publish(kSimCommandChannel, &command);
  }
  // waits for the answer to request `id`
  std::optional<sim_command_result_lcmt> answer(std::int64_t id) {
    eventually([&] {
      peer_.handleTimeout(5);
      for (const auto& r : results_) {
        if (r.request_id == id) return true;
      }
      return false;
    });
    for (const auto& r : results_) {
      if (r.request_id == id) return r;
    }
    return std::nullopt;
  }
  void on_result(const lcm::ReceiveBuffer*, const std::string&, const sim_command_result_lcmt* result) {
    results_.push_back(*result);
  }

  // the MC stands the robot up by itself: the pushes shove a standing robot
  McConfig config_ = [] {
    McConfig config = default_config();
    config.startup = Startup::Stand;
    return config;
  }();
  Mc mc_;
  LinkFaultSet links_;
  std::FILE* log_;
  SimControlAdapter adapter_;
  lcm::LCM peer_;
  std::vector<sim_command_result_lcmt> results_;
};

TEST_F(SimControlLockstep, APushCommandShovesTheStandingRobotSideways) {
  run_for(3.0);  // up and standing
  const double y_before_m = mc_.simulation().ground_truth().position[1];
  send(7, "push 0 40 0 0.1");  // 4 N s to the left
  ASSERT_TRUE(eventually([&] { return adapter_.counters().taken == 1; }));
  run_for(0.1);
  const GroundTruth pushed = mc_.simulation().ground_truth();
  // 4 N s on about 8.5 kg: some 0.4 m/s of the body's sideways speed, which a planted stance resists
  EXPECT_GT(pushed.velocity_world[1], 0.15);
  EXPECT_GT(largest_sideways_shift_m(y_before_m, 0.5), 0.005);
  const std::optional<sim_command_result_lcmt> result = answer(7);
  ASSERT_TRUE(result);
  EXPECT_EQ(result->result, 0);
  EXPECT_NE(result->reason.find("taken: push 0 40 0 0.1"), std::string::npos) << result->reason;
}

TEST_F(SimControlLockstep, WithoutAPushTheSameStandDoesNotDrift) {
  // the test above can fail: the robot alone keeps still
  run_for(3.0);
  const double y_before_m = mc_.simulation().ground_truth().position[1];
  run_for(0.1);
  EXPECT_LT(std::abs(mc_.simulation().ground_truth().velocity_world[1]), 0.05);
  EXPECT_LT(largest_sideways_shift_m(y_before_m, 0.5), 0.002);
}

TEST_F(SimControlLockstep, RefusalsAreAnsweredWithTheReasonAndMalformedPacketsOnlyCounted) {
  send(1, "push 0 0 9999 0.1");
  const std::optional<sim_command_result_lcmt> refused = answer(1);
  ASSERT_TRUE(refused);
  EXPECT_EQ(refused->result, 1);
  EXPECT_NE(refused->reason.find("above the limit of 500 N"), std::string::npos) << refused->reason;

  const std::vector<std::uint8_t> garbage(64, 0xAB);  // wrong fingerprint
  peer_.publish(kSimCommandChannel, garbage.data(), static_cast<unsigned>(garbage.size()));
  sim_command_lcmt big;
  big.request_id = 2;
  big.command = "push 0 0 1 0.1" + std::string(2000, ' ');  // oversized
  peer_.publish(kSimCommandChannel, &big);
  ASSERT_TRUE(eventually([&] { return adapter_.counters().malformed == 2; }));
  EXPECT_EQ(adapter_.counters().refused, 1u);
  EXPECT_EQ(adapter_.counters().taken, 0u);
  peer_.handleTimeout(50);
  EXPECT_EQ(results_.size(), 1u);  // only the well-formed command got an answer
}

TEST(SimControlOnARealRobot, EveryCommandIsRefusedWithTheReasonSoPushAndFaultDoNotWaitInVain) {
  const std::string url = "udpm://239.255.76.67:7690?ttl=0";
  std::FILE* log = std::tmpfile();
  SimControlAdapter adapter(nullptr, nullptr, nullptr, url, log);
  lcm::LCM peer(url);
  std::optional<sim_command_result_lcmt> answer;
  struct Handler {
    std::optional<sim_command_result_lcmt>* answer;
    void on_result(const lcm::ReceiveBuffer*, const std::string&, const sim_command_result_lcmt* result) {
      *answer = *result;
    }
  } handler{&answer};
  peer.subscribe(kSimCommandResultChannel, &Handler::on_result, &handler);
  sim_command_lcmt command;
  command.request_id = 3;
  command.command = "push 0 40 0 0.1";
  peer.publish(kSimCommandChannel, &command);
  ASSERT_TRUE(eventually([&] {
    peer.handleTimeout(5);
    return answer.has_value();
  }));
  EXPECT_EQ(answer->result, 1);
  EXPECT_NE(answer->reason.find("this MC drives a real robot"), std::string::npos) << answer->reason;
  EXPECT_EQ(adapter.counters().refused, 1u);
  adapter.finish(log);
  std::fclose(log);
}

TEST_F(SimControlLockstep, AFaultCommandReachesTheRobotAndTheMcProtectsIt) {
  run_for(3.0);  // up and standing
  send(11, "fault motor RR_hip disconnected for 1");
  ASSERT_TRUE(eventually([&] { return adapter_.counters().taken == 1; }));
  run_for(0.1);
  EXPECT_EQ(mc_.machine().status().motor_faults[7], kMotorDisconnected);
  EXPECT_EQ(mc_.machine().status().switch_status, SwitchStatus::HighDamping);
  const std::optional<sim_command_result_lcmt> result = answer(11);
  ASSERT_TRUE(result);
  EXPECT_EQ(result->result, 0);
  EXPECT_EQ(result->reason, "taken: fault motor 7 disconnected for 1");
  // the fault clears itself after 1 s, and the protection 0.5 s later
  run_for(1.5);
  EXPECT_EQ(mc_.machine().status().motor_faults[7], kMotorOk);
  EXPECT_NE(mc_.machine().status().switch_status, SwitchStatus::HighDamping);
  send(12, "fault motor 12 disconnected");
  const std::optional<sim_command_result_lcmt> refused = answer(12);
  ASSERT_TRUE(refused);
  EXPECT_EQ(refused->result, 1);
  EXPECT_NE(refused->reason.find("motor must be 0..11"), std::string::npos) << refused->reason;
}

}  // namespace
}  // namespace cerebellum
