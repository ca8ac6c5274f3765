// Motor SDK over LCM, paced at real time: how long from publishing a motor_ctrl frame with a new
// command until the first spi_data whose measured torque shows it. The MC (simulated robot,
// speed 1) runs in its own thread with the LCM adapter; a client streams frames at 500 Hz like
// the official library and, at random moments (seeded), flips the FR abad feed-forward torque
// between +0.5 and -0.5 N m (kp = kd = 0, so the motor's torque is exactly the command).
// Opens LCM sockets: run it inside a private network namespace.
//
//   scripts/netns_run.sh build/bench/motor_sdk_latency [--seconds=N] [Google Benchmark options]
#include <benchmark/benchmark.h>
#include <lcm/lcm-cpp.hpp>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include "loop/mc.hpp"
#include "loop/simulated_robot.hpp"
#include "io/lcm_motor_sdk/lcm_motor_sdk_adapter.hpp"
#include "io/lcm_motor_sdk/motor_sdk_wire.hpp"
#include "timed_benchmark_main.hpp"

namespace cerebellum {
namespace {

using Clock = std::chrono::steady_clock;
constexpr double kTorqueStepNm = 0.5;
constexpr double kReflectedToleranceNm = 0.05;

double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

double percentile(const std::vector<double>& sorted_values, double fraction) {
  if (sorted_values.empty()) return 0.0;
  return sorted_values[static_cast<std::size_t>(fraction * static_cast<double>(sorted_values.size() - 1))];
}

// streams motor_ctrl at 500 Hz and watches spi_data / motor_ctrl_state
class StreamingClient {
 public:
  explicit StreamingClient(const std::string& url) : sender_lcm_(url), receiver_lcm_(url) {
    receiver_lcm_.subscribe("spi_data", &StreamingClient::on_spi_data, this);
    receiver_lcm_.subscribe("motor_ctrl_state", &StreamingClient::on_state, this);
    receiver_ = std::thread([this] {
      while (running_.load()) receiver_lcm_.handleTimeout(5);
    });
    sender_ = std::thread([this] { send_loop(); });
  }
  ~StreamingClient() {
    running_.store(false);
    sender_.join();
    receiver_.join();
  }

  // flips the torque target; returns its generation
  int next_step() { return generation_.fetch_add(1) + 1; }
  bool reflected(int generation) const { return reflected_generation_.load() >= generation; }
  double latency_s() const {
    return std::chrono::duration<double>(reflected_at_.load() - published_at_.load()).count();
  }
  int err_flag() const { return err_flag_.load(); }

 private:
  // generation 0: the all-zero activation frame; then alternately +step and -step
  static double target_nm(int generation) {
    return generation == 0 ? 0.0 : (generation % 2 == 1 ? kTorqueStepNm : -kTorqueStepNm);
  }

  void send_loop() {
    Clock::time_point next = Clock::now();
    int published_generation = 0;
    while (running_.load()) {
      next += std::chrono::microseconds(2000);
      std::this_thread::sleep_until(next);
      const int generation = generation_.load();
      JointCommand frame;
      frame.tau_ff[0] = target_nm(generation);
      const motor_ctrl_lcmt message = encode_motor_ctrl(frame);
      if (generation != published_generation) published_at_.store(Clock::now());
      sender_lcm_.publish("motor_ctrl", &message);
      if (generation != published_generation) {
        published_generation = generation;
        published_generation_.store(generation);
      }
    }
  }

  void on_spi_data(const lcm::ReceiveBuffer*, const std::string&, const spi_data_t* msg) {
    const int generation = published_generation_.load();
    if (generation > reflected_generation_.load() &&
        std::abs(msg->tau_abad[0] - target_nm(generation)) < kReflectedToleranceNm) {
      reflected_at_.store(Clock::now());
      reflected_generation_.store(generation);
    }
  }
  void on_state(const lcm::ReceiveBuffer*, const std::string&, const motor_ctrl_state_lcmt* msg) {
    err_flag_.store(msg->err_flag);
  }

  lcm::LCM sender_lcm_;
  lcm::LCM receiver_lcm_;
  std::atomic<bool> running_{true};
  std::atomic<int> generation_{0};
  std::atomic<int> published_generation_{0};
  std::atomic<int> reflected_generation_{0};
  std::atomic<Clock::time_point> published_at_{};
  std::atomic<Clock::time_point> reflected_at_{};
  std::atomic<int> err_flag_{-1};
  std::thread receiver_;
  std::thread sender_;
};

void motor_ctrl_to_spi_data_latency(benchmark::State& state, double seconds) {
  for (auto _ : state) {
    McConfig config = default_config();
    config.startup = Startup::Damper;
    config.motor_sdk.enabled = true;
    Mc mc = make_simulated_mc(config);
    // declared before the adapter: its thread logs until the adapter is gone
    const std::unique_ptr<std::FILE, int (*)(std::FILE*)> log(std::fopen("/dev/null", "w"), &std::fclose);
    LcmMotorSdkAdapter adapter(config.motor_sdk, log.get());
    mc.arbiter().add_low_level_source(adapter.source());
    mc.loop().add_observer(adapter);
    std::atomic<bool> stop{false};
    RunStats stats;
    std::thread mc_thread([&] { stats = mc.loop().run({-1.0, 1.0}, stop); });

    std::vector<double> latencies_ms;
    std::uint64_t missed = 0;
    {
      StreamingClient client(config.motor_sdk.control_url);
      // all-zero frames until the MC clears err_flag bit1 (2 s after entering motor mode)
      const Clock::time_point activation = Clock::now();
      while (client.err_flag() != 0 && seconds_since(activation) < 10.0) {
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
      }
      latencies_ms.reserve(static_cast<std::size_t>(seconds * 60.0));
      std::mt19937 rng(11);
      std::uniform_int_distribution<int> pause_us(10000, 30000);
      const Clock::time_point begin = Clock::now();
      while (client.err_flag() == 0 && seconds_since(begin) < seconds) {
        std::this_thread::sleep_for(std::chrono::microseconds(pause_us(rng)));
        const int generation = client.next_step();
        const Clock::time_point asked = Clock::now();
        while (!client.reflected(generation) && seconds_since(asked) < 0.1) {
          std::this_thread::sleep_for(std::chrono::microseconds(50));
        }
        if (client.reflected(generation)) {
          latencies_ms.push_back(1e3 * client.latency_s());
        } else {
          ++missed;
        }
      }
    }
    stop.store(true);
    mc_thread.join();
    adapter.finish(log.get());

    std::sort(latencies_ms.begin(), latencies_ms.end());
    const MotorSdkCounters counters = adapter.source().counters();
    state.counters["p50_ms"] = percentile(latencies_ms, 0.50);
    state.counters["p99_ms"] = percentile(latencies_ms, 0.99);
    state.counters["max_ms"] = latencies_ms.empty() ? 0.0 : latencies_ms.back();
    state.counters["samples"] = static_cast<double>(latencies_ms.size());
    state.counters["missed"] = static_cast<double>(missed);
    state.counters["frames"] = static_cast<double>(counters.frames_accepted);
    state.counters["lost"] = static_cast<double>(counters.commands_lost);
    state.counters["late_substeps"] = static_cast<double>(stats.late_substeps);
    state.counters["telemetry_drop"] = static_cast<double>(adapter.telemetry_dropped());
  }
}

}  // namespace
}  // namespace cerebellum

int main(int argc, char** argv) {
  return cerebellum::run_timed_benchmark(argc, argv, "MotorCtrlToSpiDataLatency", 30.0,
                                         cerebellum::motor_ctrl_to_spi_data_latency);
}
