// Real-time factor of the whole control loop (MuJoCo physics at 1 kHz + estimator + stand-up
// controller + guard at 500 Hz) in lockstep headless mode. Run pinned to one core
// (bench/run.sh does): robot seconds per wall second is reported as "rtf".
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <string>
#include <vector>

#include "loop/control_loop.hpp"
#include "loop/lockstep_client.hpp"
#include "loop/simulated_robot.hpp"
#include "backend/mujoco_backend.hpp"
#include "control/stand_up_controller.hpp"
#include "estimation/kinematic_estimator.hpp"

namespace {

using namespace cerebellum;

MujocoBackendConfig bench_config(bool noise) {
  MujocoBackendConfig config;
  config.model_path = std::string(CEREBELLUM_MODEL_DIR) + "/cyberdog2.xml";
  config.noise.enabled = noise;
  return config;
}

// one iteration = 1 s of robot time (500 ticks) of a robot standing up and holding
void BM_StandLoopOneRobotSecond(benchmark::State& bench) {
  MujocoBackend backend(bench_config(bench.range(0) != 0));
  KinematicEstimator estimator;
  StandUpController stand_up(default_stand_up_config());
  ControlLoop loop(backend, estimator, stand_up, GuardLimits{}, 0.002);
  double robot_seconds = 0.0;
  for (auto _ : bench) {
    for (int i = 0; i < 500; ++i) loop.tick();
    robot_seconds += 1.0;
  }
  bench.counters["rtf"] = benchmark::Counter(robot_seconds, benchmark::Counter::kIsRate);
  bench.counters["tick_us"] =
      benchmark::Counter(robot_seconds * 500 * 1e-6, benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_StandLoopOneRobotSecond)->Arg(0)->Arg(1)->ArgName("noise")->Unit(benchmark::kMillisecond)->MinTime(2.0);

// the physics alone: one MuJoCo step with the motor drivers
void BM_PhysicsStep(benchmark::State& bench) {
  MujocoBackend backend(bench_config(false));
  for (auto _ : bench) backend.advance(0.001);
}
BENCHMARK(BM_PhysicsStep)->Unit(benchmark::kMicrosecond);

// the tick's wall time while the whole MC walks (gait 3 at 1 m/s, the MPC solving on its worker):
// the loop hands the MPC its input at one tick and takes the solution at a later one, waiting
// there if the solve is late (docs/architecture.md: that wait keeps lockstep runs deterministic).
// p50, p99 and the longest tick of 5 s of robot time, the robot's own stand-up before it not
// counted, their mean and the real-time factor they add up to
void BM_WalkingTickWallTime(benchmark::State& bench) {
  for (auto _ : bench) {
    const McConfig config = default_config();
    Mc mc = make_simulated_mc(config);
    LockstepClient client(mc);
    client.run(high_level_command(ModeId::RecoveryStand, 0), 3.0);
    std::vector<double> tick_us;
    tick_us.reserve(2600);
    using Clock = std::chrono::steady_clock;
    Clock::time_point before = Clock::now();
    client.run(high_level_command(ModeId::Locomotion, 3, 1.0), 5.0, [&](const CycleRecord&) {
      const Clock::time_point now = Clock::now();
      tick_us.push_back(std::chrono::duration<double, std::micro>(now - before).count());
      before = now;
    });
    // robot seconds per wall second while walking: with taskset -c 1 the MPC's worker shares
    // the loop's core, so this is the whole MC on one core
    double walking_us = 0.0;
    for (const double us : tick_us) walking_us += us;
    bench.counters["rtf"] = static_cast<double>(tick_us.size()) * config.loop_period_s * 1e6 / walking_us;
    bench.counters["mean_us"] = walking_us / static_cast<double>(tick_us.size());
    std::sort(tick_us.begin(), tick_us.end());
    bench.counters["p50_us"] = tick_us[tick_us.size() / 2];
    bench.counters["p99_us"] = tick_us[tick_us.size() * 99 / 100];
    bench.counters["max_us"] = tick_us.back();
  }
}
BENCHMARK(BM_WalkingTickWallTime)->Iterations(1)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
