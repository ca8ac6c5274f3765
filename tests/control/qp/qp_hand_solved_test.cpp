// Small QPs with answers worked out by hand, solved by every solver.
#include <gtest/gtest.h>

#include <limits>
#include <memory>
#include <string>

#include "control/qp/qp_solver_factory.hpp"

namespace cerebellum::qp {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kTol = 1e-8;

class QpHandSolved : public ::testing::TestWithParam<QpSolverKind> {
 protected:
  QpStatus solve(const QpProblem& problem) {
    solver_ = make_qp_solver(GetParam(), problem.dimensions());
    return solver_->solve(problem, solution_);
  }
  std::unique_ptr<QpSolver> solver_;
  QpSolution solution_;
};

TEST_P(QpHandSolved, UnconstrainedMinimumIsMinusHInverseG) {
  // H = [4 1; 1 2], g = [1 1]: H^-1 = [2 -1; -1 4] / 7, x = -H^-1 g = [-1 -3] / 7
  QpProblem p;
  p.resize({2, 0, 0});
  p.hessian << 4.0, 1.0, 1.0, 2.0;
  p.linear << 1.0, 1.0;
  ASSERT_EQ(solve(p), QpStatus::Solved);
  EXPECT_NEAR(solution_.x(0), -1.0 / 7.0, kTol);
  EXPECT_NEAR(solution_.x(1), -3.0 / 7.0, kTol);
  EXPECT_NEAR(solution_.objective, -2.0 / 7.0, kTol);  // 0.5 g' x
}

TEST_P(QpHandSolved, OneActiveUpperBound) {
  // min 0.5 |x|^2 - x1 - x2 s.t. x1 <= 0.5: x = (0.5, 1), multiplier 1 - x1 = 0.5 on the upper
  // bound
  QpProblem p;
  p.resize({2, 0, 1});
  p.hessian.setIdentity();
  p.linear << -1.0, -1.0;
  p.ineq_matrix << 1.0, 0.0;
  p.ineq_upper << 0.5;
  ASSERT_EQ(solve(p), QpStatus::Solved);
  EXPECT_NEAR(solution_.x(0), 0.5, kTol);
  EXPECT_NEAR(solution_.x(1), 1.0, kTol);
  EXPECT_NEAR(solution_.objective, -0.875, kTol);
  EXPECT_NEAR(solution_.ineq_multipliers(0), 0.5, 1e-7);
  EXPECT_EQ(solution_.ineq_state[0], RowState::AtUpper);
}

TEST_P(QpHandSolved, OneActiveLowerBound) {
  // min 0.5 x^2 + 2 x s.t. 1 <= x <= 3: x = 1, x + 2 + l = 0 gives l = -3 (lower bound)
  QpProblem p;
  p.resize({1, 0, 1});
  p.hessian << 1.0;
  p.linear << 2.0;
  p.ineq_matrix << 1.0;
  p.ineq_lower << 1.0;
  p.ineq_upper << 3.0;
  ASSERT_EQ(solve(p), QpStatus::Solved);
  EXPECT_NEAR(solution_.x(0), 1.0, kTol);
  EXPECT_NEAR(solution_.objective, 2.5, kTol);
  EXPECT_NEAR(solution_.ineq_multipliers(0), -3.0, 1e-7);
  EXPECT_EQ(solution_.ineq_state[0], RowState::AtLower);
}

TEST_P(QpHandSolved, InactiveBoundsLeaveTheUnconstrainedMinimum) {
  // min 0.5 |x|^2 - (1, 2) x with loose bounds: x = (1, 2), all multipliers zero
  QpProblem p;
  p.resize({2, 0, 2});
  p.hessian.setIdentity();
  p.linear << -1.0, -2.0;
  p.ineq_matrix << 1.0, 0.0, 1.0, 1.0;
  p.ineq_lower << -10.0, -kInf;
  p.ineq_upper << 10.0, 5.0;
  ASSERT_EQ(solve(p), QpStatus::Solved);
  EXPECT_NEAR(solution_.x(0), 1.0, kTol);
  EXPECT_NEAR(solution_.x(1), 2.0, kTol);
  EXPECT_NEAR(solution_.ineq_multipliers.cwiseAbs().maxCoeff(), 0.0, 1e-7);
  EXPECT_EQ(solution_.ineq_state[0], RowState::Inactive);
  EXPECT_EQ(solution_.ineq_state[1], RowState::Inactive);
}

TEST_P(QpHandSolved, EqualityOnlyProjectsOntoThePlane) {
  // min 0.5 |x|^2 s.t. x1 + x2 + x3 = 3: x = (1, 1, 1), x + l (1, 1, 1) = 0 gives l = -1
  QpProblem p;
  p.resize({3, 1, 0});
  p.hessian.setIdentity();
  p.eq_matrix << 1.0, 1.0, 1.0;
  p.eq_rhs << 3.0;
  ASSERT_EQ(solve(p), QpStatus::Solved);
  for (Eigen::Index i = 0; i < 3; ++i) EXPECT_NEAR(solution_.x(i), 1.0, kTol);
  EXPECT_NEAR(solution_.objective, 1.5, kTol);
  EXPECT_NEAR(solution_.eq_multipliers(0), -1.0, 1e-7);
}

TEST_P(QpHandSolved, EqualityAndBoundTogether) {
  // min 0.5 |x|^2 s.t. x1 + x2 = 2, x1 >= 1.5: x = (1.5, 0.5);
  // stationarity: x1 + le + li = 0, x2 + le = 0 -> le = -0.5, li = -1 (lower bound)
  QpProblem p;
  p.resize({2, 1, 1});
  p.hessian.setIdentity();
  p.eq_matrix << 1.0, 1.0;
  p.eq_rhs << 2.0;
  p.ineq_matrix << 1.0, 0.0;
  p.ineq_lower << 1.5;
  ASSERT_EQ(solve(p), QpStatus::Solved);
  EXPECT_NEAR(solution_.x(0), 1.5, kTol);
  EXPECT_NEAR(solution_.x(1), 0.5, kTol);
  EXPECT_NEAR(solution_.eq_multipliers(0), -0.5, 1e-7);
  EXPECT_NEAR(solution_.ineq_multipliers(0), -1.0, 1e-7);
  EXPECT_EQ(solution_.ineq_state[0], RowState::AtLower);
}

TEST_P(QpHandSolved, BoxCornerWithScaledHessian) {
  // min (x1 - 3)^2 + 2 (x2 + 4)^2 in the box [-1, 1]^2: separable, so x = (1, -1);
  // H = diag(2, 4), g = (-6, 16); multipliers: 2 - 6 + l1 = 0 -> 4, -4 + 16 + l2 = 0 -> -12
  QpProblem p;
  p.resize({2, 0, 2});
  p.hessian << 2.0, 0.0, 0.0, 4.0;
  p.linear << -6.0, 16.0;
  p.ineq_matrix.setIdentity();
  p.ineq_lower << -1.0, -1.0;
  p.ineq_upper << 1.0, 1.0;
  ASSERT_EQ(solve(p), QpStatus::Solved);
  EXPECT_NEAR(solution_.x(0), 1.0, kTol);
  EXPECT_NEAR(solution_.x(1), -1.0, kTol);
  EXPECT_NEAR(solution_.ineq_multipliers(0), 4.0, 1e-7);
  EXPECT_NEAR(solution_.ineq_multipliers(1), -12.0, 1e-7);
  EXPECT_NEAR(solution_.objective, 1.0 + 2.0 - 6.0 - 16.0, kTol);
}

INSTANTIATE_TEST_SUITE_P(BothSolvers, QpHandSolved,
                         ::testing::Values(QpSolverKind::GoldfarbIdnani, QpSolverKind::Alglib), [](const auto& info) {
                           return info.param == QpSolverKind::GoldfarbIdnani ? std::string("GoldfarbIdnani")
                                                                             : std::string("Alglib");
                         });

TEST(QpSolverFactory, NamesSelectTheSolver) {
  EXPECT_EQ(qp_solver_kind_from_name("goldfarb_idnani"), QpSolverKind::GoldfarbIdnani);
  EXPECT_EQ(qp_solver_kind_from_name("alglib"), QpSolverKind::Alglib);
  EXPECT_FALSE(qp_solver_kind_from_name("osqp").has_value());
  EXPECT_EQ(make_qp_solver(QpSolverKind::GoldfarbIdnani, {})->name(), "goldfarb_idnani");
  EXPECT_EQ(make_qp_solver(QpSolverKind::Alglib, {})->name(), "alglib");
}

}  // namespace
}  // namespace cerebellum::qp
