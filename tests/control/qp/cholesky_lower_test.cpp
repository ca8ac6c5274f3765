// The Goldfarb-Idnani solver's factorisation, against Eigen's own Cholesky (an independent
// implementation) and against its definition L L' = H.
#include "control/qp/cholesky_lower.hpp"

#include <gtest/gtest.h>

#include <Eigen/Cholesky>
#include <random>

namespace cerebellum::qp {
namespace {

constexpr double kMinPivotRatio = 1e-13;
constexpr double kUntouched = 7.0;

Eigen::MatrixXd random_positive_definite(std::mt19937& rng, Eigen::Index n) {
  std::normal_distribution<double> normal(0.0, 1.0);
  Eigen::MatrixXd b(2 * n + 3, n);
  for (Eigen::Index i = 0; i < b.size(); ++i) b.data()[i] = normal(rng);
  return b.transpose() * b + 1e-3 * Eigen::MatrixXd::Identity(n, n);
}

TEST(CholeskyLower, FactorsPositiveDefiniteMatricesLikeEigensCholesky) {
  std::mt19937 rng(11);
  for (const Eigen::Index n : {1, 2, 7, 60, 120}) {
    const Eigen::MatrixXd h = random_positive_definite(rng, n);
    Eigen::MatrixXd lower = Eigen::MatrixXd::Constant(n, n, kUntouched);
    ASSERT_TRUE(cholesky_lower(h, kMinPivotRatio, lower)) << n;
    const Eigen::MatrixXd l = lower.triangularView<Eigen::Lower>();
    EXPECT_LE((l * l.transpose() - h).norm(), 1e-12 * h.norm()) << n;
    const Eigen::MatrixXd reference = Eigen::LLT<Eigen::MatrixXd>(h).matrixL();
    EXPECT_LE((l - reference).norm(), 1e-9 * reference.norm()) << n;
    for (Eigen::Index j = 1; j < n; ++j) {
      for (Eigen::Index i = 0; i < j; ++i) EXPECT_EQ(lower(i, j), kUntouched) << n << ": " << i << ", " << j;
    }
  }
}

TEST(CholeskyLower, ReadsOnlyTheLowerTriangle) {
  std::mt19937 rng(12);
  const Eigen::MatrixXd h = random_positive_definite(rng, 9);
  Eigen::MatrixXd lower_only = h;
  lower_only.triangularView<Eigen::StrictlyUpper>().setConstant(-1e9);
  Eigen::MatrixXd from_full(9, 9), from_lower(9, 9);
  ASSERT_TRUE(cholesky_lower(h, kMinPivotRatio, from_full));
  ASSERT_TRUE(cholesky_lower(lower_only, kMinPivotRatio, from_lower));
  EXPECT_TRUE(from_full.triangularView<Eigen::Lower>().toDenseMatrix().isApprox(
      from_lower.triangularView<Eigen::Lower>().toDenseMatrix()));
}

TEST(CholeskyLower, RefusesIndefiniteSemidefiniteAndZeroMatrices) {
  Eigen::MatrixXd lower(3, 3);
  Eigen::MatrixXd indefinite = Eigen::Vector3d(2.0, -1.0, 3.0).asDiagonal();
  EXPECT_FALSE(cholesky_lower(indefinite, kMinPivotRatio, lower));
  const Eigen::Vector3d v(1.0, 2.0, 3.0);
  const Eigen::MatrixXd rank_one = v * v.transpose();
  EXPECT_FALSE(cholesky_lower(rank_one, kMinPivotRatio, lower));
  EXPECT_FALSE(cholesky_lower(Eigen::MatrixXd::Zero(3, 3), kMinPivotRatio, lower));
}

}  // namespace
}  // namespace cerebellum::qp
