// state_estimator and leg_control_data over real LCM sockets, inside a private network namespace:
// LcmStateFeedback's rates, and `cerebellum sim` publishing them once at 50 Hz whether the
// high-level interface, the motor SDK or both are enabled (issue 13: only the motor SDK did).
#include <gtest/gtest.h>
#include <lcm/lcm-cpp.hpp>

#include <atomic>
#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "core/robot_model.hpp"
#include "io/lcm_motor_sdk/lcm_state_feedback.hpp"
#include "leg_control_data_lcmt.hpp"
#include "state_estimator_lcmt.hpp"

namespace cerebellum {
namespace {

namespace fs = std::filesystem;
constexpr const char* kLegControlUrl = "udpm://239.255.76.67:7667?ttl=255";
constexpr const char* kEstimatorUrl = "udpm://239.255.76.67:7669?ttl=255";
constexpr std::int64_t kFeedbackPeriodNs = 20000000;

// counts both messages and keeps the state_estimator timestamps (robot time, ns)
class StateFeedbackListener {
 public:
  StateFeedbackListener() : legs_(kLegControlUrl), trunk_(kEstimatorUrl) {
    legs_.subscribe("leg_control_data", &StateFeedbackListener::on_legs, this);
    trunk_.subscribe("state_estimator", &StateFeedbackListener::on_trunk, this);
  }
  void pump(double timeout_s) {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
    while (std::chrono::steady_clock::now() < deadline) pump_once();
  }
  void pump_once() {
    legs_.handleTimeout(2);
    trunk_.handleTimeout(2);
  }

  int leg_count = 0;
  std::vector<std::int64_t> timestamps_ns;

 private:
  void on_legs(const lcm::ReceiveBuffer*, const std::string&, const leg_control_data_lcmt*) { ++leg_count; }
  void on_trunk(const lcm::ReceiveBuffer*, const std::string&, const state_estimator_lcmt* msg) {
    timestamps_ns.push_back(msg->timestamp);
  }

  lcm::LCM legs_;
  lcm::LCM trunk_;
};

CycleRecord record_at(std::uint64_t tick) {
  CycleRecord record;
  record.tick = tick;
  record.state.valid = true;
  record.state.time_s = tick * 0.002;
  record.state.q = robot::whole_body_pose(robot::kStandPose);
  return record;
}

TEST(StateFeedbackSockets, EveryTenthTickIdleAndEveryTickInMotorMode) {
  MotorSdkSource source{MotorSdkParameters{}};
  LcmStateFeedback feedback(kLegControlUrl, kEstimatorUrl, 0.002, &source);
  StateFeedbackListener listener;
  // idle: ticks 0..19 give ticks 0 and 10
  for (std::uint64_t tick = 0; tick < 20; ++tick) feedback.on_cycle(record_at(tick));
  listener.pump(0.3);
  EXPECT_EQ(listener.timestamps_ns.size(), 2u);
  EXPECT_EQ(listener.leg_count, 2);
  // motor mode: every tick
  source.on_latched(record_at(20).state);
  for (std::uint64_t tick = 20; tick < 25; ++tick) feedback.on_cycle(record_at(tick));
  listener.pump(0.3);
  EXPECT_EQ(listener.timestamps_ns.size(), 7u);
  EXPECT_EQ(listener.leg_count, 7);
  feedback.finish();
  EXPECT_EQ(feedback.published(), 7u);
  EXPECT_EQ(feedback.dropped(), 0u);
}

TEST(StateFeedbackSockets, WithoutTheMotorSdkEveryTenthTick) {
  LcmStateFeedback feedback(kLegControlUrl, kEstimatorUrl, 0.002, nullptr);
  StateFeedbackListener listener;
  for (std::uint64_t tick = 0; tick < 30; ++tick) feedback.on_cycle(record_at(tick));
  listener.pump(0.3);
  EXPECT_EQ(listener.timestamps_ns.size(), 3u);
  EXPECT_EQ(listener.leg_count, 3);
}

std::string read_file(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// runs `cerebellum sim` for 2 s of robot time with the given config sections while listening
void listen_to_sim(StateFeedbackListener& listener, const std::string& name, const std::string& sections) {
  const fs::path dir = fs::temp_directory_path() / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream(dir / "sim.yaml") << "mc:\n  startup: damper\n" << sections;
  std::atomic<bool> sim_done{false};
  int sim_status = -1;
  std::thread sim([&] {
    const std::string command =
        "cd " + dir.string() + " && " + CEREBELLUM_EXE + " sim --speed 1 --duration 2 --config sim.yaml > sim.log 2>&1";
    sim_status = std::system(command.c_str());
    sim_done = true;
  });
  while (!sim_done) listener.pump_once();
  sim.join();
  listener.pump(0.1);
  EXPECT_EQ(sim_status, 0) << read_file(dir / "sim.log");
  fs::remove_all(dir);
}

// about 100 messages in 2 s of robot time, one per 20 ms: none missing in the middle, none twice
void expect_once_at_50hz(const StateFeedbackListener& listener) {
  const std::vector<std::int64_t>& t = listener.timestamps_ns;
  ASSERT_GE(t.size(), 90u) << "state_estimator is not published at 50 Hz";
  EXPECT_LE(t.size(), 101u);
  for (std::size_t i = 1; i < t.size(); ++i) {
    ASSERT_NEAR(static_cast<double>(t[i] - t[i - 1]), static_cast<double>(kFeedbackPeriodNs), 1e4)
        << "message " << i << (t[i] == t[i - 1] ? ": published twice" : "");
  }
  EXPECT_NEAR(listener.leg_count, static_cast<int>(t.size()), 2);
}

TEST(StateFeedbackSockets, SimWithOnlyTheHighLevelInterfacePublishesStateEstimatorAndLegControlDataAt50Hz) {
  StateFeedbackListener listener;
  listen_to_sim(listener, "state_feedback_highlevel", "highlevel:\n  enabled: true\n");
  expect_once_at_50hz(listener);
}

TEST(StateFeedbackSockets, SimWithBothInterfacesPublishesEachMessageOnceAt50Hz) {
  StateFeedbackListener listener;
  listen_to_sim(listener, "state_feedback_both", "highlevel:\n  enabled: true\nmotor_sdk:\n  enabled: true\n");
  expect_once_at_50hz(listener);
}

}  // namespace
}  // namespace cerebellum
