#include "control/qp/qp_problem.hpp"

#include <cmath>
#include <limits>

namespace cerebellum::qp {

void QpProblem::resize(const QpDimensions& dims) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  hessian.setZero(dims.variables, dims.variables);
  linear.setZero(dims.variables);
  eq_matrix.setZero(dims.equalities, dims.variables);
  eq_rhs.setZero(dims.equalities);
  ineq_matrix.setZero(dims.inequalities, dims.variables);
  ineq_lower.setConstant(dims.inequalities, -inf);
  ineq_upper.setConstant(dims.inequalities, inf);
}

QpDimensions QpProblem::dimensions() const { return {hessian.rows(), eq_matrix.rows(), ineq_matrix.rows()}; }

bool has_valid_shape_and_values(const QpProblem& p) {
  const Eigen::Index n = p.hessian.rows();
  const Eigen::Index m_eq = p.eq_matrix.rows();
  const Eigen::Index m_in = p.ineq_matrix.rows();
  const bool shapes_agree = n > 0 && p.hessian.cols() == n && p.linear.size() == n && p.eq_matrix.cols() == n &&
                            p.eq_rhs.size() == m_eq && p.ineq_matrix.cols() == n && p.ineq_lower.size() == m_in &&
                            p.ineq_upper.size() == m_in;
  if (!shapes_agree) return false;
  // bounds may be infinite but never NaN
  const bool bounds_not_nan = !p.ineq_lower.hasNaN() && !p.ineq_upper.hasNaN();
  return bounds_not_nan && p.hessian.allFinite() && p.linear.allFinite() && p.eq_matrix.allFinite() &&
         p.eq_rhs.allFinite() && p.ineq_matrix.allFinite();
}

bool has_crossed_bounds(const QpProblem& p) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  for (Eigen::Index i = 0; i < p.ineq_lower.size(); ++i) {
    const double lb = p.ineq_lower(i);
    const double ub = p.ineq_upper(i);
    if (lb > ub || lb == inf || ub == -inf) return true;
  }
  return false;
}

double qp_objective(const QpProblem& p, const Eigen::Ref<const Eigen::VectorXd>& x,
                    Eigen::Ref<Eigen::VectorXd> scratch) {
  scratch.noalias() = p.hessian.selfadjointView<Eigen::Lower>() * x;
  return 0.5 * x.dot(scratch) + p.linear.dot(x);
}

}  // namespace cerebellum::qp
