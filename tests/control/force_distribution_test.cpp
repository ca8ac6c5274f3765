// The balance QP: forces reproduce a feasible wrench, respect the friction pyramid and the
// normal-force bounds, satisfy the KKT conditions, and agree with ALGLIB's minimizer.
#include "control/force_distribution.hpp"

#include <gtest/gtest.h>

#include <random>

#include "control/balance_controller.hpp"
#include "control/qp/alglib_qp_solver.hpp"
#include "control/qp/qp_kkt_check.hpp"

namespace cerebellum {
namespace {

using Feet = std::array<Eigen::Vector3d, kNumLegs>;
using Forces = std::array<Eigen::Vector3d, kNumLegs>;
using Limits = std::array<double, kNumLegs>;

constexpr double kMu = 0.4;

// feet of a standing robot relative to its centre of mass (world-aligned)
Feet standing_feet() {
  return {Eigen::Vector3d(0.17, -0.13, -0.24), Eigen::Vector3d(0.17, 0.13, -0.24), Eigen::Vector3d(-0.17, -0.13, -0.24),
          Eigen::Vector3d(-0.17, 0.13, -0.24)};
}

// the wrench forces produce about the centre of mass, summed independently of the solver's matrix
Vector6d wrench_of(const Feet& feet, const Forces& forces) {
  Vector6d w = Vector6d::Zero();
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
    w.head<3>() += forces[leg];
    w.tail<3>() += feet[leg].cross(forces[leg]);
  }
  return w;
}

void expect_within_friction_and_bounds(const Forces& forces, const Limits& limits) {
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
    const Eigen::Vector3d& f = forces[leg];
    if (limits[leg] <= 0.0) {
      EXPECT_TRUE(f.isZero()) << "unloaded leg " << leg;
      continue;
    }
    EXPECT_GE(f.z(), -1e-7) << leg;
    EXPECT_LE(f.z(), std::min(limits[leg], 150.0) + 1e-7) << leg;
    EXPECT_LE(std::abs(f.x()), kMu * f.z() + 1e-7) << leg;
    EXPECT_LE(std::abs(f.y()), kMu * f.z() + 1e-7) << leg;
  }
}

TEST(ForceDistribution, StandingWeightIsSharedEquallyBySymmetricFeet) {
  ForceDistribution distribution;
  const Feet feet = standing_feet();
  const Limits limits{150, 150, 150, 150};
  const Vector6d demanded = gravity_wrench(8.5);
  Forces forces{};
  ASSERT_EQ(distribution.solve(feet, limits, demanded, forces), qp::QpStatus::Solved);
  EXPECT_LT((wrench_of(feet, forces) - demanded).norm(), 0.02);
  for (const Eigen::Vector3d& f : forces) {
    EXPECT_NEAR(f.z(), demanded(2) / 4.0, 0.01);
    EXPECT_NEAR(f.x(), 0.0, 1e-6);
    EXPECT_NEAR(f.y(), 0.0, 1e-6);
  }
}

TEST(ForceDistribution, FeasibleRandomWrenchesAreReproducedAndSatisfyKkt) {
  ForceDistribution distribution;
  qp::AlglibQpSolver reference(qp::QpDimensions{12, 0, 20});
  qp::QpSolution reference_solution;
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (int trial = 0; trial < 200; ++trial) {
    // random feet and random forces strictly inside the cones: the wrench they make is feasible
    Feet feet{};
    Forces truth{};
    for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
      feet[leg] = standing_feet()[leg] + 0.05 * Eigen::Vector3d(unit(rng), unit(rng), unit(rng));
      const double fz = 45.0 + 35.0 * unit(rng);
      truth[leg] = {0.3 * kMu * fz * unit(rng), 0.3 * kMu * fz * unit(rng), fz};
    }
    const Vector6d demanded = wrench_of(feet, truth);
    const Limits limits{150, 150, 150, 150};
    Forces forces{};
    ASSERT_EQ(distribution.solve(feet, limits, demanded, forces), qp::QpStatus::Solved) << trial;
    EXPECT_LT((wrench_of(feet, forces) - demanded).norm(), 0.05) << trial;
    expect_within_friction_and_bounds(forces, limits);
    // optimality from the problem alone, and the same minimizer from another solver
    const qp::fixtures::KktResiduals kkt =
        qp::fixtures::kkt_residuals(distribution.last_problem(), distribution.last_solution());
    EXPECT_LT(kkt.worst(), 1e-6) << trial;
    ASSERT_EQ(reference.solve(distribution.last_problem(), reference_solution), qp::QpStatus::Solved);
    // the regularised problem is strictly convex: one minimizer (the null-space directions of the
    // wrench map are weakly curved, so forces agree to 0.01 N and the objective much closer)
    const double own_objective =
        qp::fixtures::objective_of(distribution.last_problem(), distribution.last_solution().x);
    const double reference_objective = qp::fixtures::objective_of(distribution.last_problem(), reference_solution.x);
    EXPECT_LE(own_objective, reference_objective + 1e-9 * std::abs(reference_objective)) << trial;
    EXPECT_LT((reference_solution.x - distribution.last_solution().x).cwiseAbs().maxCoeff(), 1e-2) << trial;
  }
}

TEST(ForceDistribution, UnloadedLegCarriesNothingAndThreeFeetBalanceTheCentreOfMassOverTheirTriangle) {
  ForceDistribution distribution;
  // centre of mass moved over the triangle of FL, RR, RL: the feet relative to it shift
  Feet feet = standing_feet();
  const Eigen::Vector3d com_shift(-0.17 / 3.0, 0.13 / 3.0, 0.0);
  for (Eigen::Vector3d& foot : feet) foot -= com_shift;
  const Limits limits{0.0, 150, 150, 150};
  const Vector6d demanded = gravity_wrench(8.5);
  Forces forces{};
  ASSERT_EQ(distribution.solve(feet, limits, demanded, forces), qp::QpStatus::Solved);
  EXPECT_EQ(distribution.loaded_feet(), 3);
  EXPECT_TRUE(forces[0].isZero());
  EXPECT_LT((wrench_of(feet, forces) - demanded).norm(), 0.02);
  expect_within_friction_and_bounds(forces, limits);
}

TEST(ForceDistribution, NormalForceLimitsAreHonouredWhenTheWrenchCannotBeMet) {
  ForceDistribution distribution;
  const Feet feet = standing_feet();
  // one leg limited to 5 N while being unloaded; a demand for more than four legs can give
  const Limits limits{5.0, 150, 150, 150};
  Vector6d demanded = gravity_wrench(8.5);
  demanded(2) = 800.0;
  Forces forces{};
  ASSERT_EQ(distribution.solve(feet, limits, demanded, forces), qp::QpStatus::Solved);
  expect_within_friction_and_bounds(forces, limits);
  EXPECT_NEAR(forces[0].z(), 5.0, 1e-6);
  // a pull on the ground cannot be made: no negative normal force, the body gets nothing
  demanded(2) = -50.0;
  ASSERT_EQ(distribution.solve(feet, limits, demanded, forces), qp::QpStatus::Solved);
  expect_within_friction_and_bounds(forces, limits);
  EXPECT_NEAR(wrench_of(feet, forces)(2), 0.0, 1e-6);
}

TEST(ForceDistribution, NoLoadedFootIsReportedInfeasible) {
  ForceDistribution distribution;
  Forces forces{};
  forces[1] = Eigen::Vector3d::Ones();
  EXPECT_EQ(distribution.solve(standing_feet(), Limits{0, 0, 0, 0}, gravity_wrench(8.5), forces),
            qp::QpStatus::Infeasible);
  for (const Eigen::Vector3d& f : forces) EXPECT_TRUE(f.isZero());
}

}  // namespace
}  // namespace cerebellum
