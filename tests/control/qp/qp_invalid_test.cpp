// Problems without a solution: infeasible constraints, invalid numbers, non-convex Hessians,
// and the iteration limit.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <memory>
#include <random>
#include <string>

#include "control/qp/goldfarb_idnani_solver.hpp"
#include "control/qp/qp_solver_factory.hpp"
#include "control/qp/random_qp.hpp"

namespace cerebellum::qp {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

QpProblem identity_qp(Eigen::Index n, Eigen::Index m_eq, Eigen::Index m_in) {
  QpProblem p;
  p.resize({n, m_eq, m_in});
  p.hessian.setIdentity();
  p.linear.setOnes();
  return p;
}

QpStatus solve_with(QpSolverKind kind, const QpProblem& p) {
  QpSolution solution;
  return make_qp_solver(kind, p.dimensions())->solve(p, solution);
}

class QpInvalid : public ::testing::TestWithParam<QpSolverKind> {};

TEST_P(QpInvalid, CrossedBoundsOnOneRowAreInfeasible) {
  QpProblem p = identity_qp(2, 0, 1);
  p.ineq_matrix << 1.0, 1.0;
  p.ineq_lower << 2.0;
  p.ineq_upper << 1.0;
  EXPECT_EQ(solve_with(GetParam(), p), QpStatus::Infeasible);
}

TEST_P(QpInvalid, ContradictingRowsAreInfeasible) {
  // x1 >= 2 and x1 <= 1 on separate rows
  QpProblem p = identity_qp(2, 0, 2);
  p.ineq_matrix << 1.0, 0.0, 1.0, 0.0;
  p.ineq_lower << 2.0, -kInf;
  p.ineq_upper << kInf, 1.0;
  EXPECT_EQ(solve_with(GetParam(), p), QpStatus::Infeasible);
}

TEST_P(QpInvalid, EqualityOutsideTheBoxIsInfeasible) {
  // x1 + x2 = 4 with x1 <= 1, x2 <= 1
  QpProblem p = identity_qp(2, 1, 2);
  p.eq_matrix << 1.0, 1.0;
  p.eq_rhs << 4.0;
  p.ineq_matrix.setIdentity();
  p.ineq_upper << 1.0, 1.0;
  EXPECT_EQ(solve_with(GetParam(), p), QpStatus::Infeasible);
}

TEST_P(QpInvalid, InconsistentEqualitiesAreInfeasible) {
  // x1 = 1 and 2 x1 = 4
  QpProblem p = identity_qp(2, 2, 0);
  p.eq_matrix << 1.0, 0.0, 2.0, 0.0;
  p.eq_rhs << 1.0, 4.0;
  EXPECT_EQ(solve_with(GetParam(), p), QpStatus::Infeasible);
}

TEST_P(QpInvalid, NaNAnywhereIsInvalidInput) {
  const QpProblem base = [] {
    QpProblem p = identity_qp(2, 1, 1);
    p.eq_matrix << 1.0, 1.0;
    p.ineq_matrix << 1.0, -1.0;
    p.ineq_lower << -1.0;
    p.ineq_upper << 1.0;
    return p;
  }();
  ASSERT_EQ(solve_with(GetParam(), base), QpStatus::Solved);
  for (int member = 0; member < 7; ++member) {
    SCOPED_TRACE("member " + std::to_string(member));
    QpProblem p = base;
    switch (member) {
      case 0: p.hessian(1, 0) = kNaN; break;
      case 1: p.linear(1) = kNaN; break;
      case 2: p.eq_matrix(0, 1) = kNaN; break;
      case 3: p.eq_rhs(0) = kNaN; break;
      case 4: p.ineq_matrix(0, 0) = kNaN; break;
      case 5: p.ineq_lower(0) = kNaN; break;
      default: p.ineq_upper(0) = kNaN; break;
    }
    EXPECT_EQ(solve_with(GetParam(), p), QpStatus::InvalidInput);
  }
}

TEST_P(QpInvalid, InfiniteCoefficientsAndSizeMismatchesAreInvalidInput) {
  QpProblem inf_hessian = identity_qp(2, 0, 0);
  inf_hessian.hessian(0, 0) = kInf;
  EXPECT_EQ(solve_with(GetParam(), inf_hessian), QpStatus::InvalidInput);

  QpProblem short_linear = identity_qp(3, 0, 0);
  short_linear.linear.resize(2);
  EXPECT_EQ(solve_with(GetParam(), short_linear), QpStatus::InvalidInput);

  QpProblem wide_rows = identity_qp(2, 0, 1);
  wide_rows.ineq_matrix.resize(1, 3);
  EXPECT_EQ(solve_with(GetParam(), wide_rows), QpStatus::InvalidInput);

  QpProblem missing_bound = identity_qp(2, 0, 2);
  missing_bound.ineq_upper.resize(1);
  EXPECT_EQ(solve_with(GetParam(), missing_bound), QpStatus::InvalidInput);

  EXPECT_EQ(solve_with(GetParam(), identity_qp(0, 0, 0)), QpStatus::InvalidInput);
}

TEST_P(QpInvalid, IndefiniteOrSingularHessianIsNotConvex) {
  QpProblem indefinite = identity_qp(2, 0, 0);
  indefinite.hessian << 1.0, 0.0, 0.0, -1.0;
  EXPECT_EQ(solve_with(GetParam(), indefinite), QpStatus::NotConvex);

  QpProblem singular = identity_qp(2, 0, 0);
  singular.hessian << 1.0, 1.0, 1.0, 1.0;
  EXPECT_EQ(solve_with(GetParam(), singular), QpStatus::NotConvex);

  QpProblem negative = identity_qp(3, 0, 0);
  negative.hessian *= -1.0;
  EXPECT_EQ(solve_with(GetParam(), negative), QpStatus::NotConvex);
}

INSTANTIATE_TEST_SUITE_P(BothSolvers, QpInvalid, ::testing::Values(QpSolverKind::GoldfarbIdnani, QpSolverKind::Alglib),
                         [](const auto& info) {
                           return info.param == QpSolverKind::GoldfarbIdnani ? std::string("GoldfarbIdnani")
                                                                             : std::string("Alglib");
                         });

TEST(QpGoldfarbIdnani, RedundantConsistentEqualitiesAreSolved) {
  // x1 = 1 and 2 x1 = 2 describe one plane
  QpProblem p = identity_qp(2, 2, 0);
  p.eq_matrix << 1.0, 0.0, 2.0, 0.0;
  p.eq_rhs << 1.0, 2.0;
  GoldfarbIdnaniSolver solver;
  QpSolution solution;
  ASSERT_EQ(solver.solve(p, solution), QpStatus::Solved);
  EXPECT_NEAR(solution.x(0), 1.0, 1e-12);
  EXPECT_NEAR(solution.x(1), -1.0, 1e-12);  // unconstrained: x2 = -g2
}

TEST(QpGoldfarbIdnani, RandomProblemsWithAContradictingPairAreInfeasible) {
  std::mt19937 rng(99);
  GoldfarbIdnaniSolver solver;
  QpSolution solution;
  std::normal_distribution<double> normal(0.0, 1.0);
  for (int k = 0; k < 60; ++k) {
    SCOPED_TRACE("problem " + std::to_string(k));
    QpProblem p = fixtures::make_random_feasible_qp(rng).problem;
    // append c' x >= v + 0.5 and c' x <= v for a random direction c
    const Eigen::Index n = p.hessian.rows();
    const Eigen::Index m = p.ineq_matrix.rows();
    const Eigen::VectorXd c = fixtures::random_matrix(rng, n, 1);
    const double v = normal(rng);
    p.ineq_matrix.conservativeResize(m + 2, n);
    p.ineq_lower.conservativeResize(m + 2);
    p.ineq_upper.conservativeResize(m + 2);
    p.ineq_matrix.row(m) = c.transpose();
    p.ineq_matrix.row(m + 1) = c.transpose();
    p.ineq_lower.tail(2) << v + 0.5, -kInf;
    p.ineq_upper.tail(2) << kInf, v;
    EXPECT_EQ(solver.solve(p, solution), QpStatus::Infeasible);
  }
}

TEST(QpGoldfarbIdnani, IterationLimitStopsTheSolve) {
  // the box corner needs two active bounds, so one iteration is not enough
  QpProblem p = identity_qp(2, 0, 2);
  p.linear << -3.0, 3.0;
  p.ineq_matrix.setIdentity();
  p.ineq_lower << -1.0, -1.0;
  p.ineq_upper << 1.0, 1.0;
  GoldfarbIdnaniSettings settings;
  settings.max_iterations = 1;
  GoldfarbIdnaniSolver limited({}, settings);
  QpSolution solution;
  EXPECT_EQ(limited.solve(p, solution), QpStatus::MaxIterations);
  EXPECT_EQ(solution.iterations, 1);
  settings.max_iterations = 2;
  GoldfarbIdnaniSolver enough({}, settings);
  EXPECT_EQ(enough.solve(p, solution), QpStatus::Solved);
  EXPECT_NEAR(solution.x(0), 1.0, 1e-12);
  EXPECT_NEAR(solution.x(1), -1.0, 1e-12);
}

}  // namespace
}  // namespace cerebellum::qp
