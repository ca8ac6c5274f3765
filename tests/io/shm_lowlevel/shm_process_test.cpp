// Two processes, as a user runs them: `cerebellum sim --speed 1` with the shared-memory interface
// enabled, and the lowlevel.h example as a separate program that stands the robot through it.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "io/shm_lowlevel/shm_test_names.hpp"

extern char** environ;

namespace cerebellum {
namespace {

using Clock = std::chrono::steady_clock;

// a child process with stdout and stderr in a file
class Child {
 public:
  Child(const std::vector<std::string>& argv, const std::string& output_path) {
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 1, output_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_adddup2(&actions, 1, 2);
    std::vector<char*> args;
    for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);
    spawned_ = posix_spawn(&pid_, args[0], &actions, nullptr, args.data(), environ) == 0;
    posix_spawn_file_actions_destroy(&actions);
  }
  ~Child() {
    if (spawned_ && !exited_) {
      ::kill(pid_, SIGKILL);
      wait_for(std::chrono::seconds(5));
    }
  }
  bool spawned() const { return spawned_; }
  pid_t pid() const { return pid_; }
  // true once exited; status() then holds the waitpid status
  bool wait_for(Clock::duration timeout) {
    const Clock::time_point until = Clock::now() + timeout;
    while (!exited_) {
      if (::waitpid(pid_, &status_, WNOHANG) == pid_) {
        exited_ = true;
      } else if (Clock::now() > until) {
        return false;
      } else {
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
      }
    }
    return true;
  }
  int status() const { return status_; }

 private:
  pid_t pid_ = -1;
  bool spawned_ = false;
  bool exited_ = false;
  int status_ = 0;
};

std::string read_file(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

bool wait_for_text(const std::string& path, const std::string& fragment, Clock::duration timeout) {
  const Clock::time_point until = Clock::now() + timeout;
  while (Clock::now() < until) {
    if (read_file(path).find(fragment) != std::string::npos) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return false;
}

TEST(ShmProcess, ExampleStandsTheSimulatedRobotFromAnotherProcess) {
  const std::string prefix = unique_shm_prefix();
  const std::string dir = ::testing::TempDir();
  const std::string config_path = dir + prefix + "config.yaml";
  const std::string sim_out = dir + prefix + "sim.out";
  const std::string example_out = dir + prefix + "example.out";
  std::ofstream(config_path) << "mc:\n  startup: damper\n"
                             << "shm:\n  enabled: true\n  name_prefix: " << prefix << "\n";

  Child sim(
      {CEREBELLUM_BINARY_DIR "/src/cli/cerebellum", "sim", "--speed", "1", "--duration", "6", "--config", config_path},
      sim_out);
  ASSERT_TRUE(sim.spawned());
  ASSERT_TRUE(wait_for_text(sim_out, "cerebellum ready", std::chrono::seconds(30))) << read_file(sim_out);
  EXPECT_TRUE(shm_object_exists("/" + prefix + "spline_shm"));

  Child example({CEREBELLUM_BINARY_DIR "/sdk/lowlevel/lowlevel_example_stand", "--prefix", prefix, "--duration", "60"},
                example_out);
  ASSERT_TRUE(example.spawned());
  ASSERT_TRUE(sim.wait_for(std::chrono::seconds(60))) << read_file(sim_out);
  // the example holds the stand until stopped
  ::kill(example.pid(), SIGINT);
  ASSERT_TRUE(example.wait_for(std::chrono::seconds(10)));

  const std::string sim_text = read_file(sim_out);
  const std::string example_text = read_file(example_out);
  EXPECT_TRUE(WIFEXITED(sim.status()) && WEXITSTATUS(sim.status()) == 0) << sim_text;
  EXPECT_TRUE(WIFEXITED(example.status()) && WEXITSTATUS(example.status()) == 0) << example_text;
  EXPECT_NE(sim_text.find("low-level client took control"), std::string::npos) << sim_text;
  EXPECT_NE(example_text.find("state received"), std::string::npos) << example_text;

  std::smatch match;
  ASSERT_TRUE(std::regex_search(sim_text, match, std::regex("trunk height ([0-9.]+) m \\(simulator truth\\)")))
      << sim_text;
  EXPECT_GE(std::stod(match[1]), 0.2) << sim_text << example_text;
  // the sim removed its objects on exit
  EXPECT_FALSE(shm_object_exists("/" + prefix + "spline_shm"));
  EXPECT_FALSE(shm_object_exists("/" + prefix + "imu_shm"));
  std::remove(config_path.c_str());
}

}  // namespace
}  // namespace cerebellum
