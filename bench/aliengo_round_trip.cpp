// The AlienGo UDP interface, paced at real time: a client streams HighCmd every 2 ms like the
// vendor's library and, at random moments (seeded), switches between mode 0 (idle stand) and
// mode 1 (force stand). Measured: from sending the first HighCmd of the new mode until the first
// HighState whose mode shows it, which happens only once the MC's state machine runs it (a round
// trip through the 500 Hz loop); and the share of the 2 ms cycles answered with a HighState.
// Opens UDP sockets on 127.0.0.1: run it inside a private network namespace.
//
//   scripts/netns_run.sh build/bench/aliengo_round_trip [--seconds=N] [Google Benchmark options]
#include <arpa/inet.h>
#include <benchmark/benchmark.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <memory>
#include <random>
#include <thread>
#include <vector>

#include "loop/simulated_robot.hpp"
#include "io/udp_aliengo/udp_aliengo_adapter.hpp"
#include "timed_benchmark_main.hpp"

namespace cerebellum {
namespace {

using Clock = std::chrono::steady_clock;

double percentile(const std::vector<double>& sorted_values, double fraction) {
  if (sorted_values.empty()) return 0.0;
  return sorted_values[static_cast<std::size_t>(fraction * static_cast<double>(sorted_values.size() - 1))];
}

class StreamingClient {
 public:
  explicit StreamingClient(int port) {
    fd_ = ::socket(AF_INET, SOCK_DGRAM, 0);
    sockaddr_in local{};
    local.sin_family = AF_INET;
    local.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    ::bind(fd_, reinterpret_cast<sockaddr*>(&local), sizeof local);
    target_.sin_family = AF_INET;
    target_.sin_port = htons(static_cast<std::uint16_t>(port));
    target_.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    receiver_ = std::thread([this] { receive_loop(); });
    sender_ = std::thread([this] { send_loop(); });
  }
  ~StreamingClient() {
    running_.store(false);
    sender_.join();
    receiver_.join();
    ::close(fd_);
  }
  // switches to the other mode; returns the mode asked for
  int switch_mode() {
    const int next = mode_.load() == 0 ? 1 : 0;
    asked_at_.store(Clock::time_point{});
    mode_.store(next);
    return next;
  }
  bool reflected(int mode) const { return reported_.load() == mode && seen_at_.load() >= asked_at_.load(); }
  double latency_s() const { return std::chrono::duration<double>(seen_at_.load() - asked_at_.load()).count(); }
  std::uint64_t sent() const { return sent_.load(); }
  std::uint64_t answered() const { return answered_.load(); }

 private:
  void send_loop() {
    Clock::time_point next = Clock::now();
    int sent_mode = -1;
    while (running_.load()) {
      next += std::chrono::microseconds(2000);
      std::this_thread::sleep_until(next);
      AlienGoCommand command;
      command.mode = mode_.load();
      std::uint8_t frame[kHighCmdBytes];
      encode_high_cmd(command, frame);
      if (command.mode != sent_mode) {
        asked_at_.store(Clock::now());
        sent_mode = command.mode;
      }
      ::sendto(fd_, frame, sizeof frame, 0, reinterpret_cast<const sockaddr*>(&target_), sizeof target_);
      sent_.fetch_add(1);
    }
  }
  void receive_loop() {
    std::uint8_t buffer[512];
    while (running_.load()) {
      pollfd waiting{fd_, POLLIN, 0};
      if (::poll(&waiting, 1, 5) <= 0) continue;
      const ssize_t got = ::recv(fd_, buffer, sizeof buffer, 0);
      AlienGoFeedback state;
      if (got <= 0 || !decode_high_state(buffer, static_cast<std::size_t>(got), state)) continue;
      answered_.fetch_add(1);
      if (state.mode != reported_.load()) {
        seen_at_.store(Clock::now());
        reported_.store(state.mode);
      }
    }
  }

  int fd_ = -1;
  sockaddr_in target_{};
  std::atomic<bool> running_{true};
  std::atomic<int> mode_{0};
  std::atomic<int> reported_{-1};
  std::atomic<Clock::time_point> asked_at_{};
  std::atomic<Clock::time_point> seen_at_{};
  std::atomic<std::uint64_t> sent_{0}, answered_{0};
  std::thread receiver_;
  std::thread sender_;
};

void high_cmd_to_high_state(benchmark::State& state, double seconds) {
  for (auto _ : state) {
    McConfig config = default_config();
    config.aliengo.port = 0;
    Mc mc = make_simulated_mc(config);
    const std::unique_ptr<std::FILE, int (*)(std::FILE*)> log(std::fopen("/dev/null", "w"), &std::fclose);
    UdpAliengoAdapter adapter(mc.client_port(HighLevelSource::AlienGoUdp), mc.aliengo_source().inbox(), config.aliengo,
                              log.get());
    mc.loop().add_observer(adapter);
    std::atomic<bool> stop{false};
    RunStats stats;
    std::thread mc_thread([&] { stats = mc.loop().run({-1.0, 1.0}, stop); });
    std::this_thread::sleep_for(std::chrono::seconds(3));  // the MC stands up by itself

    std::vector<double> latencies_ms;
    std::uint64_t missed = 0, sent = 0, answered = 0;
    {
      StreamingClient client(adapter.port());
      std::this_thread::sleep_for(std::chrono::seconds(1));
      std::mt19937 rng(5);
      std::uniform_int_distribution<int> pause_ms(300, 600);  // the QP stand settles between switches
      const std::uint64_t sent_before = client.sent(), answered_before = client.answered();
      const Clock::time_point begin = Clock::now();
      while (std::chrono::duration<double>(Clock::now() - begin).count() < seconds) {
        std::this_thread::sleep_for(std::chrono::milliseconds(pause_ms(rng)));
        const int mode = client.switch_mode();
        const Clock::time_point asked = Clock::now();
        while (!client.reflected(mode) && Clock::now() - asked < std::chrono::milliseconds(200)) {
          std::this_thread::sleep_for(std::chrono::microseconds(50));
        }
        if (client.reflected(mode)) {
          latencies_ms.push_back(1e3 * client.latency_s());
        } else {
          ++missed;
        }
      }
      sent = client.sent() - sent_before;
      answered = client.answered() - answered_before;
    }
    stop.store(true);
    mc_thread.join();
    adapter.finish(log.get());
    std::sort(latencies_ms.begin(), latencies_ms.end());
    state.counters["p50_ms"] = percentile(latencies_ms, 0.50);
    state.counters["p99_ms"] = percentile(latencies_ms, 0.99);
    state.counters["max_ms"] = latencies_ms.empty() ? 0.0 : latencies_ms.back();
    state.counters["samples"] = static_cast<double>(latencies_ms.size());
    state.counters["missed"] = static_cast<double>(missed);
    state.counters["answered_pct"] = sent > 0 ? 100.0 * static_cast<double>(answered) / static_cast<double>(sent) : 0.0;
    state.counters["late_substeps"] = static_cast<double>(stats.late_substeps);
  }
}

}  // namespace
}  // namespace cerebellum

int main(int argc, char** argv) {
  return cerebellum::run_timed_benchmark(argc, argv, "HighCmdToHighStateRoundTrip", 10.0,
                                         cerebellum::high_cmd_to_high_state);
}
