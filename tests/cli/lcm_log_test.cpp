// `cerebellum log` and `cerebellum replay` on LCM traffic (in a private network namespace): one
// message per interface channel, published on its port, is recorded once into the file of its
// port; the lcm-spy jar decodes every recorded message; a replay publishes them again on their
// own ports in the recorded order.
#include <gtest/gtest.h>

#include <filesystem>
#include <lcm/eventlog.h>
#include <lcm/lcm.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <fcntl.h>

#include <chrono>
#include <map>
#include <thread>

#include "danger_states_lcmt.hpp"
#include "file_recv_lcmt.hpp"
#include "file_send_lcmt.hpp"
#include "leg_control_data_lcmt.hpp"
#include "localization_lcmt.hpp"
#include "motor_ctrl_lcmt.hpp"
#include "motor_ctrl_state_lcmt.hpp"
#include "robot_control_cmd_lcmt.hpp"
#include "robot_control_response_lcmt.hpp"
#include "spi_data_t.hpp"
#include "state_estimator_lcmt.hpp"
#include "viz/tool_test_support.hpp"

extern char** environ;

namespace cerebellum {
namespace {

using Clock = std::chrono::steady_clock;
constexpr const char* kProbe = "cerebellum_test_probe";
constexpr std::array<int, 4> kPorts = {7667, 7669, 7670, 7671};

struct ChannelCase {
  int port;
  std::string channel;
  std::string java_class;
  std::string marker;  // what the decoded fields must show
  std::vector<std::uint8_t> bytes;
};

template <typename Message>
std::vector<std::uint8_t> encode(const Message& message) {
  std::vector<std::uint8_t> bytes(static_cast<std::size_t>(message.getEncodedSize()));
  message.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
  return bytes;
}

// the interface's channels on their ports (docs/lcm-types.md), each with a recognisable value
std::vector<ChannelCase> channel_cases() {
  robot_control_cmd_lcmt cmd{};
  cmd.mode = 11;
  robot_control_response_lcmt response{};
  response.mode = 12;
  file_send_lcmt gait_file{};
  gait_file.data = "gait-marker";
  file_recv_lcmt gait_result{};
  gait_result.result = 3;
  localization_lcmt odometry{};
  odometry.xyz[0] = 1.5f;
  danger_states_lcmt temperature{};
  temperature.motor_temperature[0] = 41.5f;
  state_estimator_lcmt estimator{};
  estimator.p[0] = 0.25f;
  leg_control_data_lcmt legs{};
  legs.q[0] = 0.75f;
  motor_ctrl_lcmt motor{};
  motor.q_des[0] = -1.25f;
  motor_ctrl_state_lcmt motor_state{};
  motor_state.err_flag = 7;
  spi_data_t spi{};
  spi.q_abad[0] = 0.5f;
  return {
      {7671, "robot_control_cmd", "lcmtypes.robot_control_cmd_lcmt", "mode=11;", encode(cmd)},
      {7670, "robot_control_response", "lcmtypes.robot_control_response_lcmt", "mode=12;", encode(response)},
      {7667, "global_to_robot", "lcmtypes.localization_lcmt", "xyz=[1.5, 0.0, 0.0];", encode(odometry)},
      {7669, "state_estimator", "lcmtypes.state_estimator_lcmt", "p=[0.25, 0.0, 0.0];", encode(estimator)},
      {7671, "user_gait_file", "lcmtypes.file_send_lcmt", "data=gait-marker;", encode(gait_file)},
      {7670, "motor_temperature", "lcmtypes.danger_states_lcmt", "motor_temperature=[41.5, 0.0,", encode(temperature)},
      {7667, "leg_control_data", "lcmtypes.leg_control_data_lcmt", "q=[0.75, 0.0,", encode(legs)},
      {7671, "user_gait_result", "lcmtypes.file_recv_lcmt", "result=3;", encode(gait_result)},
      {7667, "motor_ctrl", "lcmtypes.motor_ctrl_lcmt", "q_des=[-1.25, 0.0,", encode(motor)},
      {7667, "motor_ctrl_state", "lcmtypes.motor_ctrl_state_lcmt", "err_flag=7;", encode(motor_state)},
      {7667, "spi_data", "lcmtypes.spi_data_t", "q_abad=[0.5, 0.0, 0.0, 0.0];", encode(spi)},
  };
}

struct LoggedEvent {
  std::int64_t timestamp_us = 0;
  int port = 0;
  std::string channel;
  std::vector<std::uint8_t> data;
};

// the complete events of a log file (one being written may end in a partial event)
std::vector<LoggedEvent> read_events(const std::string& path, int port) {
  std::vector<LoggedEvent> events;
  lcm_eventlog_t* log = lcm_eventlog_create(path.c_str(), "r");
  if (!log) return events;
  while (lcm_eventlog_event_t* event = lcm_eventlog_read_next_event(log)) {
    const auto* data = static_cast<const std::uint8_t*>(event->data);
    events.push_back({event->timestamp, port, std::string(event->channel, event->channellen),
                      std::vector<std::uint8_t>(data, data + event->datalen)});
    lcm_eventlog_free_event(event);
  }
  lcm_eventlog_destroy(log);
  return events;
}

std::size_t count_channel(const std::vector<LoggedEvent>& events, const std::string& channel) {
  return static_cast<std::size_t>(
      std::count_if(events.begin(), events.end(), [&](const LoggedEvent& e) { return e.channel == channel; }));
}

class Publisher {
 public:
  Publisher() {
    for (int port : kPorts) {
      const std::string url = "udpm://239.255.76.67:" + std::to_string(port) + "?ttl=0";
      lcm_[port] = lcm_create(url.c_str());
    }
  }
  ~Publisher() {
    for (auto& [port, lcm] : lcm_) lcm_destroy(lcm);
  }
  bool ok() const {
    return std::all_of(lcm_.begin(), lcm_.end(), [](const auto& entry) { return entry.second != nullptr; });
  }
  void publish(int port, const std::string& channel, const std::vector<std::uint8_t>& bytes) {
    lcm_publish(lcm_.at(port), channel.c_str(), bytes.data(), static_cast<unsigned>(bytes.size()));
  }

 private:
  std::map<int, lcm_t*> lcm_;
};

// a running `cerebellum log PREFIX`, its output going to PREFIX.out
class Recording {
 public:
  explicit Recording(const std::string& prefix) : prefix_(prefix) {
    const std::vector<std::string> command = {CEREBELLUM_EXECUTABLE, "log", prefix};
    std::vector<char*> argv;
    for (const auto& arg : command) argv.push_back(const_cast<char*>(arg.c_str()));
    argv.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 1, (prefix + ".out").c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_adddup2(&actions, 1, 2);
    EXPECT_EQ(posix_spawn(&pid_, argv[0], &actions, nullptr, argv.data(), environ), 0);
    posix_spawn_file_actions_destroy(&actions);
  }
  ~Recording() {
    if (pid_ > 0) stop();
  }

  std::string file(int port) const { return prefix_ + "." + std::to_string(port) + ".lcmlog"; }
  std::vector<LoggedEvent> events(int port) const { return read_events(file(port), port); }

  // publishes probes until every port's logger has written one (bounded)
  bool wait_until_listening(Publisher& publisher) {
    const auto deadline = Clock::now() + std::chrono::seconds(10);
    while (Clock::now() < deadline) {
      for (int port : kPorts) publisher.publish(port, kProbe, {0, 0, 0, 0, 0, 0, 0, 0});
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
      if (std::all_of(kPorts.begin(), kPorts.end(),
                      [&](int port) { return count_channel(events(port), kProbe) > 0; })) {
        return true;
      }
    }
    return false;
  }

  // waits until every case's channel is in its port's file (bounded)
  bool wait_for(const std::vector<ChannelCase>& cases) {
    const auto deadline = Clock::now() + std::chrono::seconds(10);
    while (Clock::now() < deadline) {
      bool all = true;
      for (const ChannelCase& c : cases) all = all && count_channel(events(c.port), c.channel) > 0;
      if (all) return true;
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    return false;
  }

  // Ctrl-C; the exit code and what the command printed
  test::CommandResult stop() {
    kill(pid_, SIGINT);
    int status = 0;
    waitpid(pid_, &status, 0);
    pid_ = -1;
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, test::read_file(prefix_ + ".out")};
  }

 private:
  std::string prefix_;
  pid_t pid_ = -1;
};

void publish_cases(Publisher& publisher, const std::vector<ChannelCase>& cases) {
  for (const ChannelCase& c : cases) {
    publisher.publish(c.port, c.channel, c.bytes);
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
}

// records every case once into dir/<name>.<port>.lcmlog
void record_cases(const test::ScratchDir& dir, const std::string& name, const std::vector<ChannelCase>& cases) {
  Publisher publisher;
  ASSERT_TRUE(publisher.ok()) << "no LCM: this test must run in the private network namespace";
  Recording recording(dir / name);
  ASSERT_TRUE(recording.wait_until_listening(publisher)) << test::read_file(dir / (name + ".out"));
  publish_cases(publisher, cases);
  ASSERT_TRUE(recording.wait_for(cases));
  const test::CommandResult stopped = recording.stop();
  EXPECT_EQ(stopped.exit_code, 0) << stopped.output;
  EXPECT_NE(stopped.output.find("log: recording 4 port(s); Ctrl-C to stop"), std::string::npos) << stopped.output;
  EXPECT_NE(stopped.output.find(dir / (name + ".7667.lcmlog") + ": "), std::string::npos) << stopped.output;
}

TEST(LcmLogTools, LogKeepsEachChannelOnceInItsPortsFile) {
  test::ScratchDir dir;
  const auto cases = channel_cases();
  record_cases(dir, "a", cases);
  for (int port : kPorts) {
    const auto events = read_events(dir / ("a." + std::to_string(port) + ".lcmlog"), port);
    std::size_t expected = 0;
    for (const ChannelCase& c : cases) {
      if (c.port != port) {
        EXPECT_EQ(count_channel(events, c.channel), 0u) << c.channel << " on port " << port;
        continue;
      }
      ++expected;
      ASSERT_EQ(count_channel(events, c.channel), 1u) << c.channel;
      const auto event =
          std::find_if(events.begin(), events.end(), [&](const auto& e) { return e.channel == c.channel; });
      EXPECT_EQ(event->data, c.bytes) << c.channel;
    }
    EXPECT_EQ(events.size() - count_channel(events, kProbe), expected) << "port " << port;
  }
}

TEST(LcmLogTools, TheLcmSpyJarDecodesEveryRecordedMessage) {
  const std::string java = CEREBELLUM_JAVA;
  if (java.empty()) GTEST_SKIP() << "Java is absent (Debian: default-jdk-headless liblcm-java): the jar was not built";
  test::ScratchDir dir;
  const auto cases = channel_cases();
  record_cases(dir, "a", cases);
  std::string logs;
  for (int port : kPorts) logs += " " + test::quoted(dir / ("a." + std::to_string(port) + ".lcmlog"));
  const std::string classpath =
      std::string(CEREBELLUM_LCM_JAR) + ":" + CEREBELLUM_TYPES_JAR + ":" + CEREBELLUM_DECODER_CLASSES;
  const auto decoded = test::run_command(test::quoted(java) + " -cp " + test::quoted(classpath) + " LcmLogDecode " +
                                         test::quoted(CEREBELLUM_TYPES_JAR) + logs);
  ASSERT_EQ(decoded.exit_code, 0) << decoded.output;
  for (const ChannelCase& c : cases) {
    // file <TAB> utime <TAB> channel <TAB> class <TAB> fields
    const std::string key = "\t" + c.channel + "\t" + c.java_class + "\t";
    const std::size_t at = decoded.output.find(key);
    ASSERT_NE(at, std::string::npos) << c.channel << " not decoded as " << c.java_class << ":\n" << decoded.output;
    const std::string line = decoded.output.substr(at, decoded.output.find('\n', at) - at);
    EXPECT_NE(line.find(c.marker), std::string::npos) << line;
  }
}

TEST(LcmLogTools, ReplayPublishesOnEachPortInTheRecordedOrder) {
  test::ScratchDir dir;
  const auto cases = channel_cases();
  record_cases(dir, "a", cases);

  Publisher publisher;
  Recording again(dir / "b");
  ASSERT_TRUE(again.wait_until_listening(publisher));
  const auto replayed = test::run_command(test::quoted(CEREBELLUM_EXECUTABLE) + " replay " + test::quoted(dir / "a"));
  ASSERT_EQ(replayed.exit_code, 0) << replayed.output;
  EXPECT_NE(replayed.output.find("replay: " + dir / "a.7669.lcmlog" + " -> udpm://239.255.76.67:7669?ttl=0"),
            std::string::npos)
      << replayed.output;
  ASSERT_TRUE(again.wait_for(cases));
  EXPECT_EQ(again.stop().exit_code, 0);

  std::vector<LoggedEvent> merged;
  for (int port : kPorts) {
    for (LoggedEvent& e : read_events(dir / ("b." + std::to_string(port) + ".lcmlog"), port)) {
      if (e.channel != kProbe) merged.push_back(std::move(e));
    }
  }
  std::stable_sort(merged.begin(), merged.end(),
                   [](const LoggedEvent& x, const LoggedEvent& y) { return x.timestamp_us < y.timestamp_us; });
  ASSERT_EQ(merged.size(), cases.size());
  for (std::size_t i = 0; i < cases.size(); ++i) {
    EXPECT_EQ(merged[i].channel, cases[i].channel) << "position " << i;
    EXPECT_EQ(merged[i].port, cases[i].port) << cases[i].channel;
    EXPECT_EQ(merged[i].data, cases[i].bytes) << cases[i].channel;
  }
}

TEST(LcmLogTools, LcmSpyScriptStartsSpyWithEveryTypeOfTheJar) {
  if (std::string(CEREBELLUM_JAVA).empty()) GTEST_SKIP() << "Java is absent: no jar, no lcm-spy";
  ASSERT_TRUE(test::on_path("xvfb-run")) << "xvfb-run missing: scripts/install_deps.sh installs xvfb and xauth";
  test::ScratchDir dir;
  const std::string out = dir / "spy.out";
  const std::string line = "CEREBELLUM_LCM_JAR=" + test::quoted(CEREBELLUM_TYPES_JAR) + " exec xvfb-run -a -n 110 " +
                           test::quoted(CEREBELLUM_SOURCE_DIR "/scripts/lcm_spy.sh") + " 7670 > " + test::quoted(out) +
                           " 2>&1";
  const std::vector<std::string> command = {"/bin/sh", "-c", line};
  std::vector<char*> argv;
  for (const auto& arg : command) argv.push_back(const_cast<char*>(arg.c_str()));
  argv.push_back(nullptr);
  // its own process group, so the window server and the JVM stop together
  posix_spawnattr_t attributes;
  posix_spawnattr_init(&attributes);
  posix_spawnattr_setpgroup(&attributes, 0);
  posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETPGROUP);
  pid_t pid = -1;
  ASSERT_EQ(posix_spawn(&pid, argv[0], nullptr, &attributes, argv.data(), environ), 0);
  posix_spawnattr_destroy(&attributes);
  // every definition of lcm/ is in the jar
  std::size_t definitions = 0;
  for (const auto& entry : std::filesystem::directory_iterator(CEREBELLUM_SOURCE_DIR "/lcm")) {
    definitions += entry.path().extension() == ".lcm" ? 1 : 0;
  }
  const std::string expected = "Found " + std::to_string(definitions) + " LCM types";
  const auto deadline = Clock::now() + std::chrono::seconds(20);
  bool found = false;
  while (!found && Clock::now() < deadline) {
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    found = test::read_file(out).find(expected) != std::string::npos;
  }
  kill(-pid, SIGTERM);
  waitpid(pid, nullptr, 0);
  EXPECT_TRUE(found) << test::read_file(out);
}

TEST(LcmLogTools, ReplayOfAMissingLogNamesWhatItLookedFor) {
  test::ScratchDir dir;
  const auto run = test::run_command(test::quoted(CEREBELLUM_EXECUTABLE) + " replay " + test::quoted(dir / "none"));
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.output.find("cerebellum replay: no log files " + dir / "none" + ".<port>.lcmlog"), std::string::npos)
      << run.output;
}

}  // namespace
}  // namespace cerebellum
