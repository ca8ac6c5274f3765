// Convex MPC timing on one core: building the condensed QP, solving it, and both, for the
// trot (swing feet removed, 60 variables) and an all-stance horizon (120 variables).
// Each benchmark times 2000 individual MPC steps of varied states and reports p50 / p99.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <random>
#include <vector>

#include "../tests/control/locomotion/walking_fixture.hpp"
#include "control/locomotion/convex_mpc.hpp"
#include "control/qp/goldfarb_idnani_solver.hpp"
#include "core/robot_model.hpp"

namespace {

using namespace cerebellum;

// a walking robot's MPC input: state and foot positions varied around a trot at 0.8 m/s
MpcInput varied_input(std::mt19937& rng, bool trot, int phase) {
  std::normal_distribution<double> noise(0.0, 1.0);
  MpcInput in;
  in.x0 << 0.02 * noise(rng), 0.02 * noise(rng), 0.3 * noise(rng), 0, 0, 0.25 + 0.01 * noise(rng), 0.2 * noise(rng),
      0.2 * noise(rng), 0.3 * noise(rng), 0.8 + 0.1 * noise(rng), 0.05 * noise(rng), 0.05 * noise(rng),
      -robot::kGravityMPerS2;
  for (int k = 0; k < kMpcHorizon; ++k) {
    in.x_ref[k] = in.x0;
    in.x_ref[k].head<3>() << 0, 0, in.x0[2];
    in.x_ref[k][3] = 0.8 * 0.03 * (k + 1);
    in.x_ref[k][5] = 0.25;
    in.x_ref[k].segment<6>(6) << 0, 0, 0, 0.8, 0, 0;
    for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
      const bool first_pair = leg == 0 || leg == 3;
      in.contact[k][leg] = !trot || (first_pair == (((k + phase) / 6) % 2 == 0));
    }
  }
  const double xs[4] = {0.18, 0.18, -0.15, -0.15}, ys[4] = {-0.13, 0.13, -0.13, 0.13};
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
    in.foot_from_com[leg] = Eigen::Vector3d(xs[leg] + 0.03 * noise(rng), ys[leg] + 0.01 * noise(rng), -0.25);
  }
  return in;
}

void report_percentiles(benchmark::State& bench, std::vector<double>& micros) {
  std::sort(micros.begin(), micros.end());
  bench.counters["p50_us"] = micros[micros.size() / 2];
  bench.counters["p99_us"] = micros[micros.size() * 99 / 100];
  bench.counters["max_us"] = micros.back();
}

template <typename Step>
void time_steps(benchmark::State& bench, bool trot, Step&& step) {
  ConvexMpc mpc(ConvexMpcConfig{}, std::make_unique<qp::GoldfarbIdnaniSolver>());
  std::mt19937 rng(3);
  std::vector<MpcInput> inputs;
  for (int i = 0; i < 2000; ++i) inputs.push_back(varied_input(rng, trot, i % 12));
  std::vector<double> micros;
  micros.reserve(inputs.size());
  for (auto _ : bench) {
    micros.clear();
    for (const MpcInput& in : inputs) {
      const auto start = std::chrono::steady_clock::now();
      step(mpc, in);
      micros.push_back(std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start).count());
    }
  }
  report_percentiles(bench, micros);
}

void BM_MpcBuildAndSolve(benchmark::State& bench) {
  time_steps(bench, bench.range(0) != 0,
             [](ConvexMpc& mpc, const MpcInput& in) { benchmark::DoNotOptimize(mpc.solve(in)); });
}
BENCHMARK(BM_MpcBuildAndSolve)->Arg(1)->Arg(0)->ArgName("trot")->Unit(benchmark::kMillisecond)->Iterations(3);

void BM_MpcBuildOnly(benchmark::State& bench) {
  time_steps(bench, bench.range(0) != 0, [](ConvexMpc& mpc, const MpcInput& in) { mpc.build(in); });
}
BENCHMARK(BM_MpcBuildOnly)->Arg(1)->Arg(0)->ArgName("trot")->Unit(benchmark::kMillisecond)->Iterations(3);

// the QP solve alone, each problem in turn: p50 / p99 of single solves and the solver's work,
// apart from the machine: bounds added and dropped per solve
void time_solves(benchmark::State& bench, const std::vector<qp::QpProblem>& problems) {
  qp::GoldfarbIdnaniSolver solver;
  qp::QpSolution solution;
  std::vector<double> micros;
  std::vector<int> iterations;
  for (auto _ : bench) {
    micros.clear();
    iterations.clear();
    for (const qp::QpProblem& p : problems) {
      const auto start = std::chrono::steady_clock::now();
      benchmark::DoNotOptimize(solver.solve(p, solution));
      micros.push_back(std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start).count());
      iterations.push_back(solution.iterations);
    }
  }
  report_percentiles(bench, micros);
  std::sort(iterations.begin(), iterations.end());
  bench.counters["iterations_p50"] = iterations[iterations.size() / 2];
  bench.counters["iterations_p99"] = iterations[iterations.size() * 99 / 100];
}

// the QP solve alone, on problems the MPC built
void BM_MpcSolveOnly(benchmark::State& bench) {
  const bool trot = bench.range(0) != 0;
  ConvexMpc mpc(ConvexMpcConfig{}, std::make_unique<qp::GoldfarbIdnaniSolver>());
  std::mt19937 rng(3);
  std::vector<qp::QpProblem> problems;
  for (int i = 0; i < 500; ++i) {
    mpc.build(varied_input(rng, trot, i % 12));
    problems.push_back(mpc.problem());
  }
  time_solves(bench, problems);
}
BENCHMARK(BM_MpcSolveOnly)->Arg(1)->Arg(0)->ArgName("trot")->Unit(benchmark::kMillisecond)->Iterations(3);

// a solver that keeps a copy of every problem it is given (called from the MPC's worker thread;
// read only once the walk, and with it the worker, has ended)
class RecordingSolver final : public qp::QpSolver {
 public:
  explicit RecordingSolver(std::vector<qp::QpProblem>& problems) : problems_(problems) {}
  qp::QpStatus solve(const qp::QpProblem& problem, qp::QpSolution& solution) override {
    problems_.push_back(problem);
    return inner_.solve(problem, solution);
  }
  std::string_view name() const override { return "recording"; }

 private:
  std::vector<qp::QpProblem>& problems_;
  qp::GoldfarbIdnaniSolver inner_;
};

// the MPC's problems of 5 s of walking with a gait at a forward speed, on the robot's estimate
std::vector<qp::QpProblem> walking_problems(int gait, double vx_m_s) {
  std::vector<qp::QpProblem> problems;
  {
    testing::WalkingSim sim(std::make_unique<RecordingSolver>(problems));
    sim.controller.set(testing::walk_command(gait, vx_m_s));
    sim.run_until(testing::StandThenWalk::kStandSeconds + 5.0);
  }
  return problems;
}

// the QP solve alone on a walk's own problems: gait 3 (trot) at 1 m/s, gait 10 (flying trot) at
// 1.6 m/s; p50 / p99 of single solves, and the bounds added and dropped per solve
void BM_MpcSolveWalking(benchmark::State& bench) {
  const bool flying = bench.range(0) != 0;
  const std::vector<qp::QpProblem> problems = walking_problems(flying ? 10 : 3, flying ? 1.6 : 1.0);
  time_solves(bench, problems);
  bench.counters["problems"] = static_cast<double>(problems.size());
  bench.counters["variables_max"] = 0;
  for (const qp::QpProblem& p : problems) {
    bench.counters["variables_max"] = std::max<double>(bench.counters["variables_max"], p.hessian.rows());
  }
}
BENCHMARK(BM_MpcSolveWalking)->Arg(0)->Arg(1)->ArgName("flying_trot")->Unit(benchmark::kMillisecond)->Iterations(3);

}  // namespace

BENCHMARK_MAIN();
