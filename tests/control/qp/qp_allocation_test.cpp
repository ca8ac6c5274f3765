// Goldfarb-Idnani reuses its workspace: repeated solves of same-sized problems never allocate.
#include <gtest/gtest.h>

#include <memory>
#include <random>
#include <vector>

#include "control/qp/allocation_counter.hpp"
#include "control/qp/condensed_mpc_qp.hpp"
#include "control/qp/goldfarb_idnani_solver.hpp"
#include "control/qp/random_qp.hpp"

namespace cerebellum::qp {
namespace {

TEST(QpAllocation, CounterSeesEigenAndStandardAllocations) {
  long counted = 0;
  {
    fixtures::AllocationCounter counter;
    Eigen::VectorXd v(64);
    auto p = std::make_unique<std::vector<int>>(16);
    v.setConstant(1.0);
    (*p)[3] = 2;
    counted = counter.count();
    volatile double keep = v.sum() + (*p)[3];
    (void)keep;
  }
  EXPECT_GE(counted, 3);
}

TEST(QpAllocation, SameSizedMpcSolvesDoNotAllocate) {
  std::mt19937 rng(5);
  const auto schedule = fixtures::stand_schedule(10);
  GoldfarbIdnaniSolver solver(fixtures::make_condensed_mpc_qp(schedule, rng).dimensions());
  QpSolution solution;
  ASSERT_EQ(solver.solve(fixtures::make_condensed_mpc_qp(schedule, rng), solution), QpStatus::Solved);
  int iterations = 0;
  for (int trial = 0; trial < 5; ++trial) {
    const QpProblem p = fixtures::make_condensed_mpc_qp(schedule, rng);
    fixtures::AllocationCounter counter;
    const QpStatus status = solver.solve(p, solution);
    const long allocations = counter.count();
    EXPECT_EQ(status, QpStatus::Solved);
    EXPECT_EQ(allocations, 0) << "trial " << trial;
    iterations += solution.iterations;
  }
  EXPECT_GT(iterations, 20);  // the solves did real work: bounds were added
}

TEST(QpAllocation, SmallerProblemsInsideTheReservationDoNotAllocate) {
  // equality rows and a degenerate constraint mix exercise the other code paths
  std::mt19937 rng(6);
  GoldfarbIdnaniSolver solver({40, 8, 160});
  QpSolution solution;
  for (int trial = 0; trial < 20; ++trial) {
    const fixtures::RandomQp qp = fixtures::make_random_feasible_qp(rng, 25);
    const QpDimensions dims = qp.problem.dimensions();
    solution.reset(dims.variables, dims.equalities, dims.inequalities);
    fixtures::AllocationCounter counter;
    const QpStatus status = solver.solve(qp.problem, solution);
    const long allocations = counter.count();
    EXPECT_EQ(status, QpStatus::Solved);
    EXPECT_EQ(allocations, 0) << "trial " << trial;
  }
}

}  // namespace
}  // namespace cerebellum::qp
