// MPC-shaped QPs: stance-foot forces under friction pyramids, checked by KKT, by the friction
// cone itself, by physics (the feet carry the body weight) and against ALGLIB.
#include <gtest/gtest.h>

#include <random>

#include "control/qp/condensed_mpc_qp.hpp"
#include "control/qp/alglib_qp_solver.hpp"
#include "control/qp/goldfarb_idnani_solver.hpp"
#include "control/qp/qp_kkt_check.hpp"
#include "core/robot_model.hpp"

namespace cerebellum::qp {
namespace {

// checks the pyramid directly on the forces: |fx|, |fy| <= mu fz and 0 <= fz <= fz_max
void expect_forces_in_pyramid(const Eigen::VectorXd& forces, const fixtures::ForceLimits& limits) {
  constexpr double kSlack = 1e-8;
  for (Eigen::Index f = 0; f + 2 < forces.size(); f += 3) {
    const double fx = forces(f);
    const double fy = forces(f + 1);
    const double fz = forces(f + 2);
    EXPECT_LE(std::abs(fx), limits.mu * fz + kSlack) << "force " << f / 3;
    EXPECT_LE(std::abs(fy), limits.mu * fz + kSlack) << "force " << f / 3;
    EXPECT_GE(fz, -kSlack);
    EXPECT_LE(fz, limits.fz_max_n + kSlack);
  }
}

// KKT residuals relative to the size of the gradient and multipliers involved
void expect_kkt(const QpProblem& p, const QpSolution& s) {
  const fixtures::KktResiduals kkt = fixtures::kkt_residuals(p, s);
  const double gradient_scale = 1.0 + p.linear.cwiseAbs().maxCoeff();
  EXPECT_LT(kkt.stationarity, 1e-9 * gradient_scale);
  EXPECT_LT(kkt.primal, 1e-8);
  EXPECT_LT(kkt.dual, 1e-12);
  EXPECT_LT(kkt.complementarity, 1e-7);
}

void expect_matches_alglib(const QpProblem& p, const QpSolution& gi) {
  AlglibQpSolver alglib;
  QpSolution reference;
  ASSERT_EQ(alglib.solve(p, reference), QpStatus::Solved);
  EXPECT_NEAR(gi.objective, reference.objective, 1e-6 * (1.0 + std::abs(gi.objective)));
  EXPECT_LT((gi.x - reference.x).cwiseAbs().maxCoeff(), 1e-3);  // newtons
}

TEST(QpMpc, DisturbedFourStepHorizonSatisfiesKkt) {
  std::mt19937 rng(11);
  const fixtures::ForceLimits limits;
  GoldfarbIdnaniSolver solver;
  QpSolution solution;
  for (int trial = 0; trial < 10; ++trial) {
    SCOPED_TRACE("trial " + std::to_string(trial));
    const QpProblem p = fixtures::make_condensed_mpc_qp(fixtures::stand_schedule(4), rng, limits);
    ASSERT_EQ(p.hessian.rows(), 48);
    ASSERT_EQ(p.ineq_matrix.rows(), 80);
    ASSERT_EQ(solver.solve(p, solution), QpStatus::Solved);
    expect_kkt(p, solution);
    expect_forces_in_pyramid(solution.x, limits);
    expect_matches_alglib(p, solution);
  }
}

TEST(QpMpc, BodyAtRestOnItsReferenceIsHeldByItsWeight) {
  // no tracking error: the forces must cancel gravity. The horizon has no terminal cost, so
  // forces fade over its last steps; the first half must carry the weight within 8 %.
  std::mt19937 rng(12);
  GoldfarbIdnaniSolver solver;
  QpSolution solution;
  const double weight_n = robot::kMpcMassKg * fixtures::kGravity;
  for (int trial = 0; trial < 5; ++trial) {
    const QpProblem p = fixtures::make_condensed_mpc_qp(fixtures::stand_schedule(10), rng, {}, false);
    ASSERT_EQ(solver.solve(p, solution), QpStatus::Solved);
    expect_kkt(p, solution);
    for (Eigen::Index step = 0; step < 5; ++step) {
      Eigen::Vector3d total = Eigen::Vector3d::Zero();
      for (Eigen::Index foot = 0; foot < 4; ++foot) {
        total += solution.x.segment<3>(12 * step + 3 * foot);
      }
      EXPECT_NEAR(total.z(), weight_n, 0.08 * weight_n) << "step " << step;
      EXPECT_NEAR(total.x(), 0.0, 0.02 * weight_n) << "step " << step;
      EXPECT_NEAR(total.y(), 0.0, 0.02 * weight_n) << "step " << step;
    }
  }
}

TEST(QpMpc, TrotAndFullHorizonsSolveWithKkt) {
  std::mt19937 rng(14);
  GoldfarbIdnaniSolver solver;
  QpSolution solution;
  for (const auto& schedule : {fixtures::trot_schedule(10, 3), fixtures::stand_schedule(10)}) {
    const QpProblem p = fixtures::make_condensed_mpc_qp(schedule, rng);
    ASSERT_EQ(solver.solve(p, solution), QpStatus::Solved);
    expect_kkt(p, solution);
    expect_forces_in_pyramid(solution.x, {});
    expect_matches_alglib(p, solution);
  }
}

TEST(QpMpc, LowFrictionMakesThePyramidBind) {
  // mu 0.05 cannot provide the random lateral wrench, so pyramid faces become active
  std::mt19937 rng(13);
  const fixtures::ForceLimits slippery{0.05, 150.0};
  GoldfarbIdnaniSolver solver;
  QpSolution solution;
  int active_faces = 0;
  for (int trial = 0; trial < 10; ++trial) {
    const QpProblem p = fixtures::make_balance_qp(rng, slippery);
    ASSERT_EQ(solver.solve(p, solution), QpStatus::Solved);
    expect_kkt(p, solution);
    expect_forces_in_pyramid(solution.x, slippery);
    expect_matches_alglib(p, solution);
    for (RowState s : solution.ineq_state) active_faces += s == RowState::Inactive ? 0 : 1;
  }
  EXPECT_GT(active_faces, 10);
}

}  // namespace
}  // namespace cerebellum::qp
