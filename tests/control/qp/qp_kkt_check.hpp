// Optimality residuals of a QP solution computed from the problem alone (independent of solvers).
#pragma once

#include <algorithm>
#include <cmath>

#include <Eigen/Core>

#include "control/qp/qp_problem.hpp"
#include "control/qp/qp_solution.hpp"

namespace cerebellum::qp::fixtures {

struct KktResiduals {
  double stationarity = 0.0;     // |H x + g + A_eq' l_eq + C' l_in|_inf
  double primal = 0.0;           // largest violation of an equality or a bound
  double dual = 0.0;             // largest multiplier pushing on a bound that does not exist
  double complementarity = 0.0;  // largest |multiplier| * distance to the bound it pushes on
  double worst() const { return std::max({stationarity, primal, dual, complementarity}); }
};

inline KktResiduals kkt_residuals(const QpProblem& p, const QpSolution& s) {
  KktResiduals r;
  const Eigen::VectorXd gradient = p.hessian * s.x + p.linear + p.eq_matrix.transpose() * s.eq_multipliers +
                                   p.ineq_matrix.transpose() * s.ineq_multipliers;
  r.stationarity = gradient.size() > 0 ? gradient.cwiseAbs().maxCoeff() : 0.0;

  const Eigen::VectorXd eq_values = p.eq_matrix * s.x;
  for (Eigen::Index k = 0; k < eq_values.size(); ++k) {
    r.primal = std::max(r.primal, std::abs(eq_values(k) - p.eq_rhs(k)));
  }
  const Eigen::VectorXd row_values = p.ineq_matrix * s.x;
  for (Eigen::Index i = 0; i < row_values.size(); ++i) {
    const double lb = p.ineq_lower(i);
    const double ub = p.ineq_upper(i);
    const double value = row_values(i);
    r.primal = std::max({r.primal, lb - value, value - ub});
    // positive multipliers push on the upper bound, negative ones on the lower bound
    const double on_upper = std::max(s.ineq_multipliers(i), 0.0);
    const double on_lower = std::max(-s.ineq_multipliers(i), 0.0);
    if (std::isfinite(ub)) {
      r.complementarity = std::max(r.complementarity, on_upper * std::abs(ub - value));
    } else {
      r.dual = std::max(r.dual, on_upper);
    }
    if (std::isfinite(lb)) {
      r.complementarity = std::max(r.complementarity, on_lower * std::abs(value - lb));
    } else {
      r.dual = std::max(r.dual, on_lower);
    }
  }
  return r;
}

// objective evaluated with the full (symmetric) H
inline double objective_of(const QpProblem& p, const Eigen::VectorXd& x) {
  return 0.5 * x.dot(p.hessian * x) + p.linear.dot(x);
}

}  // namespace cerebellum::qp::fixtures
