// Random strictly convex QPs that are feasible by construction: every constraint is built
// around a known point x0 (equalities pass through it, bounds bracket it).
#pragma once

#include <algorithm>
#include <limits>
#include <random>

#include <Eigen/Core>

#include "control/qp/qp_problem.hpp"

namespace cerebellum::qp::fixtures {

struct RandomQp {
  QpProblem problem;
  Eigen::VectorXd feasible_point;
};

inline Eigen::MatrixXd random_matrix(std::mt19937& rng, Eigen::Index rows, Eigen::Index cols) {
  std::normal_distribution<double> normal(0.0, 1.0);
  Eigen::MatrixXd m(rows, cols);
  for (Eigen::Index j = 0; j < cols; ++j) {
    for (Eigen::Index i = 0; i < rows; ++i) m(i, j) = normal(rng);
  }
  return m;
}

// H = M M' / n + 0.05 I; rows of C are random, with some duplicated or scaled copies and some
// lb == ub rows so degenerate active sets occur
inline RandomQp make_random_feasible_qp(std::mt19937& rng, int max_variables = 25) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  std::uniform_int_distribution<int> pick_n(1, max_variables);
  const Eigen::Index n = pick_n(rng);
  std::uniform_int_distribution<int> pick_eq(0, static_cast<int>(std::min<Eigen::Index>(n - 1, 4)));
  std::uniform_int_distribution<int> pick_in(0, static_cast<int>(3 * n));
  std::uniform_real_distribution<double> unit(0.0, 1.0);

  RandomQp out;
  QpProblem& p = out.problem;
  p.resize({n, pick_eq(rng), pick_in(rng)});
  const Eigen::MatrixXd m = random_matrix(rng, n, n);
  p.hessian = m * m.transpose() / static_cast<double>(n) + 0.05 * Eigen::MatrixXd::Identity(n, n);
  p.linear = 3.0 * random_matrix(rng, n, 1);
  out.feasible_point = random_matrix(rng, n, 1);
  const Eigen::VectorXd& x0 = out.feasible_point;

  p.eq_matrix = random_matrix(rng, p.eq_matrix.rows(), n);
  p.eq_rhs = p.eq_matrix * x0;

  for (Eigen::Index i = 0; i < p.ineq_matrix.rows(); ++i) {
    const double kind = unit(rng);
    if (i > 0 && kind < 0.08) {
      // scaled copy of the previous row: parallel normals
      p.ineq_matrix.row(i) = (0.5 + unit(rng)) * p.ineq_matrix.row(i - 1);
    } else {
      p.ineq_matrix.row(i) = random_matrix(rng, 1, n);
    }
    const double value = p.ineq_matrix.row(i).dot(x0);
    const double lower = value - unit(rng);
    const double upper = value + unit(rng);
    const double sides = unit(rng);
    if (sides < 0.05) {
      p.ineq_lower(i) = value;  // lb == ub
      p.ineq_upper(i) = value;
    } else if (sides < 0.35) {
      p.ineq_lower(i) = lower;
      p.ineq_upper(i) = inf;
    } else if (sides < 0.65) {
      p.ineq_lower(i) = -inf;
      p.ineq_upper(i) = upper;
    } else {
      p.ineq_lower(i) = lower;
      p.ineq_upper(i) = upper;
    }
  }
  return out;
}

}  // namespace cerebellum::qp::fixtures
