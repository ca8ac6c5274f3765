// Shared-memory low-level interface, paced at real time: how long after a client sets the command
// flag it sees the state of the cycle that took the frame, and how many of the MC's own 1 ms
// updates started late. The MC (simulated robot, speed 1) runs in its own thread; the client
// thread stands the robot up and holds it, setting each command at a random phase of the 1 ms
// cycle (seeded) and spinning on the flags until the answer arrives.
//
//   shm_latency [--seconds=N] [Google Benchmark options]     (N: wall seconds, default 60)
#include <benchmark/benchmark.h>
#include <sched.h>
#include <sys/mman.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <memory>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include "loop/mc.hpp"
#include "loop/simulated_robot.hpp"
#include "io/shm_lowlevel/shm_lowlevel_port.hpp"
#include "lowlevel/lowlevel_sync.h"
#include "timed_benchmark_main.hpp"

namespace cerebellum {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

double percentile(std::vector<double>& sorted_values, double fraction) {
  if (sorted_values.empty()) return 0.0;
  const auto index = static_cast<std::size_t>(fraction * static_cast<double>(sorted_values.size() - 1));
  return sorted_values[index];
}

// lying pose reached from the start in 1 s, stand pose 1.5 s later, then held
void stand_frame(double t_s, const leg_state_t (&start)[4], leg_control_t (&legs)[4]) {
  constexpr double kPi = 3.14159265358979323846;
  const double lying[3] = {0.0, 80.0 * kPi / 180.0, -135.0 * kPi / 180.0};
  const double stand[3] = {0.0, 45.0 * kPi / 180.0, -70.0 * kPi / 180.0};
  std::memset(legs, 0, sizeof(legs));
  for (std::size_t leg = 0; leg < 4; ++leg) {
    const double from_start[3] = {start[leg].abad.p, start[leg].hip.p, start[leg].knee.p};
    joint_control_t* joints[3] = {&legs[leg].abad, &legs[leg].hip, &legs[leg].knee};
    for (std::size_t j = 0; j < 3; ++j) {
      const double q = t_s < 1.0 ? from_start[j] + (lying[j] - from_start[j]) * t_s
                                 : lying[j] + (stand[j] - lying[j]) * std::min((t_s - 1.0) / 1.5, 1.0);
      joints[j]->p_des = static_cast<float>(q);
      joints[j]->kp = 60.0f;
      joints[j]->kd = 2.0f;
    }
    legs[leg].flags = 1;
  }
}

void shm_command_to_state_latency(benchmark::State& state, double seconds) {
  for (auto _ : state) {
    McConfig config = default_config();
    config.startup = Startup::Damper;
    config.shm.enabled = true;
    config.shm.name_prefix = "cbbench" + std::to_string(::getpid()) + "_";
    Mc mc = make_simulated_mc(config);
    // declared before the port: its log thread writes until the port is gone
    const std::unique_ptr<std::FILE, int (*)(std::FILE*)> log(std::fopen("/dev/null", "w"), &std::fclose);
    ShmLowLevelPort port(config.shm, config.safety, log.get());
    mc.arbiter().add_low_level_source(port.source());
    mc.loop().add_substep_participant(port);
    spline_data_p shm = create_spline_shm_named(port.spline_object_name().c_str());
    nav_imu_p imu = create_imu_shm_named(port.imu_object_name().c_str());

    std::atomic<bool> stop{false};
    RunStats stats;
    std::thread mc_thread([&] { stats = mc.loop().run({-1.0, 1.0}, stop); });

    leg_state_t start[4];
    nav_imu_t imu_frame{};
    while (!lowlevel_read_state(shm, imu, CONSUMER_CONTROL, start, &imu_frame)) std::this_thread::yield();

    std::vector<double> latencies_us;
    latencies_us.reserve(static_cast<std::size_t>(seconds * 1200.0));
    std::mt19937 rng(7);
    std::uniform_int_distribution<int> phase_us(0, 999);
    std::uint64_t busy_cycles = 0;
    leg_control_t frame[4];
    std::uint32_t* command_flag = lowlevel_command_flag(shm);
    std::uint32_t* state_flag = lowlevel_state_flag(shm, CONSUMER_CONTROL);
    std::size_t* stamp = lowlevel_imu_timestamp(imu);
    const Clock::time_point begin = Clock::now();
    while (seconds_since(begin) < seconds) {
      std::this_thread::sleep_for(std::chrono::microseconds(phase_us(rng)));
      stand_frame(seconds_since(begin), start, frame);
      const std::size_t stamp_before = __atomic_load_n(stamp, __ATOMIC_ACQUIRE);
      if (!lowlevel_write_command(shm, frame)) {
        ++busy_cycles;
        continue;
      }
      const Clock::time_point flag_set = Clock::now();
      // taken, and a state newer than the one before the flag was set is complete
      while (__atomic_load_n(command_flag, __ATOMIC_ACQUIRE) != 0 ||
             __atomic_load_n(state_flag, __ATOMIC_ACQUIRE) == 0 ||
             __atomic_load_n(stamp, __ATOMIC_ACQUIRE) == stamp_before) {
        sched_yield();
      }
      latencies_us.push_back(1e6 * seconds_since(flag_set));
    }
    stop.store(true);
    mc_thread.join();

    std::sort(latencies_us.begin(), latencies_us.end());
    const ShmLowLevelCounters counters = port.source().counters();
    state.counters["p50_us"] = percentile(latencies_us, 0.50);
    state.counters["p99_us"] = percentile(latencies_us, 0.99);
    state.counters["max_us"] = latencies_us.empty() ? 0.0 : latencies_us.back();
    state.counters["samples"] = static_cast<double>(latencies_us.size());
    state.counters["client_busy"] = static_cast<double>(busy_cycles);
    state.counters["mc_cycles"] = static_cast<double>(counters.cycles);
    state.counters["late_substeps"] = static_cast<double>(stats.late_substeps);
    state.counters["cmd_timeouts"] = static_cast<double>(counters.command_timeouts);
    state.counters["robot_s"] = stats.robot_time_s;
    state.counters["height_m"] = mc.simulation().ground_truth().position[2];
    ::munmap(shm, LOWLEVEL_SPLINE_SHM_SIZE);
    ::munmap(imu, LOWLEVEL_IMU_SHM_SIZE);
  }
}

}  // namespace
}  // namespace cerebellum

int main(int argc, char** argv) {
  return cerebellum::run_timed_benchmark(argc, argv, "ShmCommandToStateLatency", 60.0,
                                         cerebellum::shm_command_to_state_latency);
}
