// The motor SDK over real LCM sockets, inside a private network namespace: malformed packets are
// counted, the adapter publishes what the loop records, the client library behaves like the
// official one, and `cerebellum sim` plus the example program stand the robot up.
#include <gtest/gtest.h>
#include <lcm/lcm-cpp.hpp>

#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <regex>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <custom_interface.hpp>

#include "core/robot_model.hpp"
#include "io/common/eventually.hpp"
#include "io/lcm_motor_sdk/lcm_motor_sdk_adapter.hpp"
#include "io/lcm_motor_sdk/motor_sdk_wire.hpp"
#include "state_estimator_lcmt.hpp"

namespace cerebellum {
namespace {

namespace fs = std::filesystem;
constexpr const char* kControlUrl = "udpm://239.255.76.67:7667?ttl=255";
constexpr const char* kEstimatorUrl = "udpm://239.255.76.67:7669?ttl=255";

std::vector<std::uint8_t> encoded_frame(const JointCommand& sdk_command) {
  const motor_ctrl_lcmt message = encode_motor_ctrl(sdk_command);
  std::vector<std::uint8_t> bytes(message.getEncodedSize());
  message.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
  return bytes;
}

// one of each bad packet, then one good frame, published raw on motor_ctrl
void publish_malformed_set(lcm::LCM& lcm) {
  const std::vector<std::uint8_t> good = encoded_frame(JointCommand{});
  std::vector<std::uint8_t> wrong_fingerprint = good;
  wrong_fingerprint[0] ^= 0x01;
  std::vector<std::uint8_t> oversized = good;
  oversized.resize(good.size() + 64, 0x5a);
  JointCommand nan_command;
  nan_command.tau_ff[7] = std::numeric_limits<double>::quiet_NaN();
  const std::vector<std::uint8_t> nan_frame = encoded_frame(nan_command);
  lcm.publish("motor_ctrl", wrong_fingerprint.data(), wrong_fingerprint.size());
  lcm.publish("motor_ctrl", good.data(), 100);  // truncated
  lcm.publish("motor_ctrl", oversized.data(), oversized.size());
  lcm.publish("motor_ctrl", nan_frame.data(), nan_frame.size());
}

TEST(MotorSdkSockets, AdapterCountsMalformedPacketsAndAcceptsGoodOnes) {
  MotorSdkConfig config;
  LcmMotorSdkAdapter adapter(config, stderr);
  lcm::LCM publisher(kControlUrl);
  ASSERT_TRUE(publisher.good());
  publish_malformed_set(publisher);
  // a packet far beyond one datagram is reassembled by LCM and still rejected
  std::vector<std::uint8_t> huge = encoded_frame(JointCommand{});
  huge.resize(100000, 0);
  publisher.publish("motor_ctrl", huge.data(), huge.size());
  const std::vector<std::uint8_t> good = encoded_frame(JointCommand{});
  publisher.publish("motor_ctrl", good.data(), good.size());

  ASSERT_TRUE(eventually([&] { return adapter.source().counters().frames_accepted == 1; }));
  ASSERT_TRUE(eventually([&] { return adapter.rejections().oversized == 2; }));
  const MotorCtrlRejections rejected = adapter.rejections();
  EXPECT_EQ(rejected.wrong_fingerprint, 1u);
  EXPECT_EQ(rejected.truncated, 1u);
  EXPECT_EQ(rejected.non_finite, 1u);
  EXPECT_TRUE(adapter.source().wants_control());
}

// collects the MC's feedback channels
class FeedbackListener {
 public:
  FeedbackListener() : control_(kControlUrl), estimator_(kEstimatorUrl) {
    control_.subscribe("spi_data", &FeedbackListener::on_spi, this);
    control_.subscribe("motor_ctrl_state", &FeedbackListener::on_state, this);
    estimator_.subscribe("state_estimator", &FeedbackListener::on_estimator, this);
  }
  // handles whatever arrives within about timeout_s
  void pump(double timeout_s) {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
    while (std::chrono::steady_clock::now() < deadline) {
      control_.handleTimeout(2);
      estimator_.handleTimeout(2);
    }
  }

  int spi_count = 0;
  int state_count = 0;
  int estimator_count = 0;
  spi_data_t spi{};
  motor_ctrl_state_lcmt state{};

 private:
  void on_spi(const lcm::ReceiveBuffer*, const std::string&, const spi_data_t* msg) { spi = *msg, ++spi_count; }
  void on_state(const lcm::ReceiveBuffer*, const std::string&, const motor_ctrl_state_lcmt* msg) {
    state = *msg, ++state_count;
  }
  void on_estimator(const lcm::ReceiveBuffer*, const std::string&, const state_estimator_lcmt*) { ++estimator_count; }

  lcm::LCM control_;
  lcm::LCM estimator_;
};

TEST(MotorSdkSockets, AdapterPublishesSpiDataAndStateOnlyInMotorModeEveryTick) {
  MotorSdkConfig config;
  LcmMotorSdkAdapter adapter(config, stderr);
  FeedbackListener listener;
  CycleRecord record;
  record.state.valid = true;
  record.state.q = robot::whole_body_pose(robot::kStandPose);
  // idle: nothing (state_estimator and leg_control_data belong to LcmStateFeedback)
  for (std::uint64_t tick = 0; tick < 20; ++tick) {
    record.tick = tick;
    adapter.on_cycle(record);
  }
  listener.pump(0.3);
  EXPECT_EQ(listener.estimator_count, 0);
  EXPECT_EQ(listener.spi_count, 0);

  // motor mode: every tick gives spi_data and motor_ctrl_state
  adapter.source().on_latched(record.state);
  for (std::uint64_t tick = 20; tick < 25; ++tick) {
    record.tick = tick;
    adapter.on_cycle(record);
  }
  listener.pump(0.3);
  EXPECT_EQ(listener.spi_count, 5);
  EXPECT_EQ(listener.state_count, 5);
  EXPECT_EQ(listener.estimator_count, 0);
  EXPECT_EQ(listener.state.err_flag, kMotorSdkCommandLost);
  EXPECT_FLOAT_EQ(listener.spi.q_hip[2], -float(robot::kStandPose[1]));
  EXPECT_FLOAT_EQ(listener.spi.q_knee[3], -float(robot::kStandPose[2]));
  EXPECT_EQ(static_cast<std::uint32_t>(listener.spi.flags[0]), 0x80000000u);
  EXPECT_EQ(adapter.telemetry_dropped(), 0u);
}

// a user program: a fixed command, and a record of what it saw
class RecordingClient final : public CustomInterface {
 public:
  RecordingClient() : CustomInterface(500.0) {}
  std::atomic<int> ticks{0};
  std::atomic<bool> last_first_run{false};
  std::atomic<float> seen_fr_hip_q{0.0f};

 private:
  void UserCode(bool first_run) override {
    last_first_run = first_run;
    seen_fr_hip_q = robot_data_.q[1];
    for (int i = 0; i < 12; ++i) {
      motor_cmd_.q_des[i] = 0.1f * (i + 1);
      motor_cmd_.qd_des[i] = 0.3f;
      motor_cmd_.kp_des[i] = 5.0f;
      motor_cmd_.kd_des[i] = 0.5f;
      motor_cmd_.tau_des[i] = 0.2f;
    }
    ++ticks;
  }
};

// the MC's side of the conversation, for the client library
class FakeMc {
 public:
  FakeMc() : lcm_(kControlUrl) { lcm_.subscribe("motor_ctrl", &FakeMc::on_frame, this); }
  // waits for the next motor_ctrl frame
  bool next_frame(motor_ctrl_lcmt& frame) {
    const int before = frames_;
    for (int n = 0; n < 500 && frames_ == before; ++n) lcm_.handleTimeout(10);
    frame = last_;
    return frames_ != before;
  }
  void publish_state(std::int16_t err_flag) {
    motor_ctrl_state_lcmt state{};
    state.err_flag = err_flag;
    lcm_.publish("motor_ctrl_state", &state);
  }
  void publish_spi(float fr_hip_wire, std::int32_t flag3) {
    spi_data_t spi{};
    spi.q_hip[0] = fr_hip_wire;
    for (int i = 0; i < 12; ++i) spi.flags[i] = static_cast<std::int32_t>(0x80000000u);
    spi.flags[3] = flag3;
    lcm_.publish("spi_data", &spi);
  }

 private:
  void on_frame(const lcm::ReceiveBuffer*, const std::string&, const motor_ctrl_lcmt* msg) { last_ = *msg, ++frames_; }
  lcm::LCM lcm_;
  motor_ctrl_lcmt last_{};
  int frames_ = 0;
};

bool all_zero(const motor_ctrl_lcmt& frame) {
  for (int i = 0; i < 12; ++i) {
    if (frame.q_des[i] != 0 || frame.qd_des[i] != 0 || frame.kp_des[i] != 0 || frame.kd_des[i] != 0 ||
        frame.tau_des[i] != 0) {
      return false;
    }
  }
  return true;
}

TEST(MotorSdkSockets, ClientLibraryActivatesSendsFlippedCommandsAndStopsOnMotorErrors) {
  FakeMc mc;
  RecordingClient client;
  std::atomic<bool> spin_returned{false};
  std::thread spinner([&] {
    client.Spin();
    spin_returned = true;
  });
  struct StopOnExit {
    RecordingClient& client;
    std::thread& spinner;
    ~StopOnExit() {
      client.Stop();
      spinner.join();
    }
  } stop_on_exit{client, spinner};

  // no motor_ctrl_state yet: err_flag starts with bit1, so only all-zero frames go out
  motor_ctrl_lcmt frame;
  for (int n = 0; n < 5; ++n) {
    ASSERT_TRUE(mc.next_frame(frame));
    EXPECT_TRUE(all_zero(frame));
  }
  EXPECT_TRUE(client.last_first_run.load());

  // the MC clears bit1 and reports the FR hip at -0.7 on the wire (+0.7 in SDK convention)
  mc.publish_spi(-0.7f, static_cast<std::int32_t>(0x80000000u));
  mc.publish_state(0);
  ASSERT_TRUE(eventually([&] {
    mc.next_frame(frame);
    return !all_zero(frame);
  }));
  EXPECT_FLOAT_EQ(frame.q_des[0], 0.1f);
  EXPECT_FLOAT_EQ(frame.q_des[1], -0.2f);
  EXPECT_FLOAT_EQ(frame.q_des[2], -0.3f);
  EXPECT_FLOAT_EQ(frame.qd_des[4], -0.3f);
  EXPECT_FLOAT_EQ(frame.tau_des[5], -0.2f);
  EXPECT_FLOAT_EQ(frame.tau_des[6], 0.2f);
  EXPECT_FLOAT_EQ(frame.kp_des[1], 5.0f);
  EXPECT_FLOAT_EQ(frame.kd_des[2], 0.5f);
  // the tick that saw bit1 cleared still ran with first_run true; the next one does not
  ASSERT_TRUE(mc.next_frame(frame));
  EXPECT_FALSE(client.last_first_run.load());
  EXPECT_FLOAT_EQ(client.seen_fr_hip_q.load(), 0.7f);

  // bit1 again: all-zero frames, first_run true
  mc.publish_state(0x02);
  ASSERT_TRUE(eventually([&] {
    mc.next_frame(frame);
    return all_zero(frame) && client.last_first_run.load();
  }));

  // a motor error bit (not the mode bits) stops the client
  mc.publish_spi(-0.7f, static_cast<std::int32_t>(0x80000001u));
  EXPECT_TRUE(eventually([&] { return spin_returned.load(); }));
}

std::string read_file(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST(MotorSdkSockets, SimAndExampleProgramStandTheRobotUp) {
  const fs::path dir = fs::temp_directory_path() / "motor_sdk_end_to_end";
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream(dir / "user.yaml") << "motor_sdk_position_mutation_limit: 1\n";
  std::ofstream(dir / "sim.yaml") << "mc:\n  startup: damper\n"
                                  << "robot:\n  model: " << CEREBELLUM_MODEL_DIR << "/cyberdog2.xml\n"
                                  << "motor_sdk:\n  enabled: true\n  user_parameter_file: user.yaml\n";
  // the sim runs 10 s of robot time at real-time speed; the example outlives it
  const std::string sim_command = "cd " + dir.string() + " && " + CEREBELLUM_EXE +
                                  " sim --speed 1 --duration 10 --config sim.yaml > sim.log 2> sim.err";
  const std::string example_command =
      "cd " + dir.string() + " && " + EXAMPLE_MOTOR_CTRL_EXE + " 11.5 > example.log 2>&1";
  int sim_status = -1, example_status = -1;
  std::thread sim([&] { sim_status = std::system(sim_command.c_str()); });
  const bool ready =
      eventually([&] { return read_file(dir / "sim.log").find("cerebellum ready") != std::string::npos; }, 30.0);
  std::thread example([&] {
    if (ready) example_status = std::system(example_command.c_str());
  });
  if (ready) {
    // bad packets in the middle of the run change nothing but the counters
    std::this_thread::sleep_for(std::chrono::milliseconds(500));
    lcm::LCM publisher(kControlUrl);
    publish_malformed_set(publisher);
  }
  sim.join();
  example.join();
  ASSERT_TRUE(ready) << read_file(dir / "sim.err");

  const std::string sim_log = read_file(dir / "sim.log");
  EXPECT_EQ(sim_status, 0) << read_file(dir / "sim.err");
  EXPECT_EQ(example_status, 0) << read_file(dir / "example.log");
  std::smatch summary;
  ASSERT_TRUE(std::regex_search(sim_log, summary, std::regex("motor sdk: motor mode yes, err_flag 0x([0-9a-f]+)")))
      << sim_log.substr(sim_log.size() > 2000 ? sim_log.size() - 2000 : 0);
  const unsigned err_flag = std::stoul(summary[1].str(), nullptr, 16);
  EXPECT_EQ(err_flag & kMotorSdkCommandLost, 0u) << "err_flag bit1 still set";
  EXPECT_NE(sim_log.find("rejected 1 wrong fingerprint, 1 truncated, 1 oversized, 1 non-finite"), std::string::npos)
      << summary.suffix().str().substr(0, 400);
  std::smatch height;
  ASSERT_TRUE(std::regex_search(sim_log, height, std::regex("trunk height ([0-9.]+) m")));
  EXPECT_GE(std::stod(height[1].str()), 0.2);
  EXPECT_NE(read_file(dir / "example.log").find("example_motor_ctrl: done after 5750 ticks"), std::string::npos);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace cerebellum
