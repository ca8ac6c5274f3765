// Random feasible QPs: Goldfarb-Idnani must satisfy the KKT conditions and agree with ALGLIB.
#include <gtest/gtest.h>

#include <random>

#include "control/qp/alglib_qp_solver.hpp"
#include "control/qp/goldfarb_idnani_solver.hpp"
#include "control/qp/qp_kkt_check.hpp"
#include "control/qp/random_qp.hpp"

namespace cerebellum::qp {
namespace {

constexpr int kProblems = 250;

TEST(QpRandom, GoldfarbIdnaniSatisfiesKktAndMatchesAlglib) {
  std::mt19937 rng(20240611);
  // one solver object for all problems: sizes change between solves
  GoldfarbIdnaniSolver gi;
  AlglibQpSolver alglib;
  QpSolution gi_solution;
  QpSolution alglib_solution;
  int active_rows = 0;
  for (int k = 0; k < kProblems; ++k) {
    SCOPED_TRACE("problem " + std::to_string(k));
    const fixtures::RandomQp qp = fixtures::make_random_feasible_qp(rng);
    ASSERT_EQ(gi.solve(qp.problem, gi_solution), QpStatus::Solved);
    const fixtures::KktResiduals kkt = fixtures::kkt_residuals(qp.problem, gi_solution);
    EXPECT_LT(kkt.stationarity, 1e-8);
    EXPECT_LT(kkt.primal, 1e-8);
    EXPECT_LT(kkt.dual, 1e-12);
    EXPECT_LT(kkt.complementarity, 1e-8);
    EXPECT_NEAR(gi_solution.objective, fixtures::objective_of(qp.problem, gi_solution.x), 1e-9);
    // the known feasible point can never beat the minimum
    EXPECT_LE(gi_solution.objective, fixtures::objective_of(qp.problem, qp.feasible_point) + 1e-9);
    for (RowState s : gi_solution.ineq_state) active_rows += s == RowState::Inactive ? 0 : 1;

    ASSERT_EQ(alglib.solve(qp.problem, alglib_solution), QpStatus::Solved);
    const double scale = 1.0 + std::abs(gi_solution.objective);
    EXPECT_NEAR(gi_solution.objective, alglib_solution.objective, 1e-6 * scale);
    EXPECT_LT((gi_solution.x - alglib_solution.x).cwiseAbs().maxCoeff(), 1e-5);
  }
  // the set must exercise constraints, not only unconstrained minima
  EXPECT_GT(active_rows, kProblems);
}

TEST(QpRandom, ReusedSolverMatchesAFreshSolver) {
  std::mt19937 rng(7);
  GoldfarbIdnaniSolver reused;
  QpSolution reused_solution;
  QpSolution fresh_solution;
  for (int k = 0; k < 40; ++k) {
    const fixtures::RandomQp qp = fixtures::make_random_feasible_qp(rng);
    GoldfarbIdnaniSolver fresh(qp.problem.dimensions());
    ASSERT_EQ(reused.solve(qp.problem, reused_solution), QpStatus::Solved);
    ASSERT_EQ(fresh.solve(qp.problem, fresh_solution), QpStatus::Solved);
    EXPECT_EQ(reused_solution.iterations, fresh_solution.iterations);
    EXPECT_LT((reused_solution.x - fresh_solution.x).cwiseAbs().maxCoeff(), 1e-12);
  }
}

}  // namespace
}  // namespace cerebellum::qp
