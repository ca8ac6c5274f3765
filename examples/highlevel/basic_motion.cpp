// Basic motion on the high-level interface: stand up (recovery stand), raise and lower the head,
// set the body height (pose control), lie down. Works against `cerebellum sim` with
// `highlevel.enabled: true` or a CyberDog2. A step the MC refuses (BAN_TRANS, for example a mode
// it does not offer) is reported and skipped. Ctrl-C sends PureDamper (7, 0) and exits.
#include <cerebellum/highlevel_client.hpp>

#include <signal.h>

#include <array>
#include <chrono>
#include <cstdio>
#include <thread>

namespace {

using cerebellum::HighLevelClient;
using cerebellum::HighLevelClientStatus;
using std::chrono::milliseconds;

struct Step {
  const char* what;
  int mode;
  int gait_id;
  std::array<float, 3> rpy_des;
  std::array<float, 3> pos_des;
  int duration_ms;    // 0: runs until replaced
  bool must_succeed;  // the example fails when this step does not complete
};

constexpr milliseconds kModeTimeout{10000};
constexpr milliseconds kPollPeriod{100};

bool interrupted() {
  sigset_t pending;
  sigpending(&pending);
  return sigismember(&pending, SIGINT) == 1 || sigismember(&pending, SIGTERM) == 1;
}

robot_control_cmd_lcmt command_of(const Step& step) {
  robot_control_cmd_lcmt command{};
  command.mode = static_cast<std::int8_t>(step.mode);
  command.gait_id = static_cast<std::int8_t>(step.gait_id);
  command.contact = 0x0F;
  for (int i = 0; i < 3; ++i) {
    command.rpy_des[i] = step.rpy_des[i];
    command.pos_des[i] = step.pos_des[i];
  }
  command.duration = step.duration_ms;
  return command;
}

// waits in short slices so Ctrl-C is noticed; Timeout also when interrupted
HighLevelClientStatus wait_for(HighLevelClient& client, const Step& step, milliseconds timeout) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  while (!interrupted()) {
    const HighLevelClientStatus status = client.wait_for_mode(step.mode, step.gait_id, kPollPeriod);
    if (status != HighLevelClientStatus::Timeout) return status;
    if (std::chrono::steady_clock::now() >= deadline) return HighLevelClientStatus::Timeout;
  }
  return HighLevelClientStatus::Timeout;
}

void lie_down_now(HighLevelClient& client) {
  robot_control_cmd_lcmt damp{};
  damp.mode = 7;
  client.send(damp);
  client.wait_for_mode(7, 0, milliseconds(2000));
}

}  // namespace

int main() {
  // Ctrl-C stays pending instead of killing the process: checked between and during steps
  sigset_t stop_signals;
  sigemptyset(&stop_signals);
  sigaddset(&stop_signals, SIGINT);
  sigaddset(&stop_signals, SIGTERM);
  pthread_sigmask(SIG_BLOCK, &stop_signals, nullptr);

  HighLevelClient client;
  if (const HighLevelClientStatus status = client.start(); status != HighLevelClientStatus::Ok) {
    std::fprintf(stderr, "basic_motion: %s: %s\n", cerebellum::to_string(status), client.last_error().c_str());
    return 1;
  }
  const std::array<Step, 5> steps{{
      {"stand up (recovery stand)", 12, 0, {0, 0, 0}, {0, 0, 0}, 0, true},
      {"head up", 21, 0, {0, 0.3f, 0}, {0, 0, 0}, 500, false},
      {"head down", 21, 0, {0, -0.3f, 0}, {0, 0, 0}, 300, false},
      {"body height 0.22 m", 21, 5, {0, 0, 0}, {0, 0, 0.22f}, 400, false},
      {"lie down (PureDamper)", 7, 0, {0, 0, 0}, {0, 0, 0}, 0, true},
  }};
  int failures = 0;
  for (const Step& step : steps) {
    const auto start = std::chrono::steady_clock::now();
    client.send(command_of(step));
    const HighLevelClientStatus status = wait_for(client, step, kModeTimeout);
    if (interrupted()) {
      std::printf("interrupted: lying down (7, 0)\n");
      lie_down_now(client);
      return 130;
    }
    const double elapsed_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const auto response = client.latest_response();
    if (status == HighLevelClientStatus::Ok) {
      std::printf("%s: mode %d gait %d reached in %.2f s\n", step.what, step.mode, step.gait_id, elapsed_s);
    } else {
      std::printf("%s: mode %d gait %d %s; the MC reports mode %d gait %d switch_status %d\n", step.what, step.mode,
                  step.gait_id, cerebellum::to_string(status), response ? response->mode : -1,
                  response ? response->gait_id : -1, response ? response->switch_status : -1);
      if (step.must_succeed) ++failures;
    }
    std::fflush(stdout);
    // a timed step holds for its duration before the next one is sent
    const auto hold_until = start + milliseconds(step.duration_ms);
    while (std::chrono::steady_clock::now() < hold_until && !interrupted())
      std::this_thread::sleep_for(milliseconds(10));
  }
  client.stop();
  std::printf("basic_motion: %s\n", failures == 0 ? "done" : "failed");
  return failures == 0 ? 0 : 1;
}
