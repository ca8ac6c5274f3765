// Goldfarb-Idnani against ALGLIB DENSE-IPM on QPs shaped like the locomotion controllers':
// the trot MPC with swing feet removed (60 variables, 100 rows), the full MPC (120, 200) and the
// 12-variable balance QP. Each benchmark cycles through 16 seeded problem instances.
#include <benchmark/benchmark.h>

#include <random>
#include <vector>

#include "../tests/control/qp/condensed_mpc_qp.hpp"
#include "control/qp/qp_solver_factory.hpp"

namespace cerebellum::qp {
namespace {

enum class Shape { Trot60, Full120, Balance12 };

std::vector<QpProblem> make_problems(Shape shape) {
  std::mt19937 rng(2024);
  std::vector<QpProblem> problems;
  for (int i = 0; i < 16; ++i) {
    switch (shape) {
      case Shape::Trot60:
        problems.push_back(fixtures::make_condensed_mpc_qp(fixtures::trot_schedule(10, 3), rng));
        break;
      case Shape::Full120:
        problems.push_back(fixtures::make_condensed_mpc_qp(fixtures::stand_schedule(10), rng));
        break;
      case Shape::Balance12: problems.push_back(fixtures::make_balance_qp(rng)); break;
    }
  }
  return problems;
}

void solve_qp(benchmark::State& state, QpSolverKind kind, Shape shape) {
  const std::vector<QpProblem> problems = make_problems(shape);
  const auto solver = make_qp_solver(kind, problems.front().dimensions());
  QpSolution solution;
  std::size_t next = 0;
  double iterations = 0.0;
  for (auto _ : state) {
    const QpStatus status = solver->solve(problems[next], solution);
    if (status != QpStatus::Solved) {
      state.SkipWithError("qp not solved");
      break;
    }
    iterations += solution.iterations;
    benchmark::DoNotOptimize(solution.x.data());
    next = (next + 1) % problems.size();
  }
  state.counters["vars"] = static_cast<double>(problems.front().hessian.rows());
  state.counters["rows"] = static_cast<double>(problems.front().ineq_matrix.rows());
  state.counters["iters"] = benchmark::Counter(iterations, benchmark::Counter::kAvgIterations);
}

BENCHMARK_CAPTURE(solve_qp, gi_trot_60x100, QpSolverKind::GoldfarbIdnani, Shape::Trot60)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(solve_qp, alglib_trot_60x100, QpSolverKind::Alglib, Shape::Trot60)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(solve_qp, gi_full_120x200, QpSolverKind::GoldfarbIdnani, Shape::Full120)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(solve_qp, alglib_full_120x200, QpSolverKind::Alglib, Shape::Full120)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(solve_qp, gi_balance_12x20, QpSolverKind::GoldfarbIdnani, Shape::Balance12)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(solve_qp, alglib_balance_12x20, QpSolverKind::Alglib, Shape::Balance12)
    ->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace cerebellum::qp

BENCHMARK_MAIN();
