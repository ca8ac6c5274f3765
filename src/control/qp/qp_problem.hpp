// Dense convex quadratic program, the input of every QpSolver.
//
//   minimize    0.5 x' H x + g' x
//   subject to  A_eq x  = b_eq                 (equality rows)
//               lb <= C x <= ub                (inequality rows, two-sided)
//
// H is symmetric positive definite; solvers read only its lower triangle.
// A one-sided row uses lb = -inf or ub = +inf; lb == ub is allowed but equalities belong in A_eq.
// NaN anywhere, or an infinite value in H, g, A_eq, b_eq or C, makes the problem invalid.
#pragma once

#include <Eigen/Core>

namespace cerebellum::qp {

struct QpDimensions {
  Eigen::Index variables = 0;
  Eigen::Index equalities = 0;
  Eigen::Index inequalities = 0;
};

struct QpProblem {
  Eigen::MatrixXd hessian;      // H, variables x variables
  Eigen::VectorXd linear;       // g, variables
  Eigen::MatrixXd eq_matrix;    // A_eq, equalities x variables
  Eigen::VectorXd eq_rhs;       // b_eq, equalities
  Eigen::MatrixXd ineq_matrix;  // C, inequalities x variables
  Eigen::VectorXd ineq_lower;   // lb, inequalities (may hold -inf)
  Eigen::VectorXd ineq_upper;   // ub, inequalities (may hold +inf)

  // sizes every member; matrices and g zeroed, bounds set to -inf / +inf (no constraint)
  void resize(const QpDimensions& dims);
  // dimensions as given by H, A_eq and C (meaningful only when the shape is valid)
  QpDimensions dimensions() const;
};

// every member has consistent sizes, at least one variable, and no NaN (no inf outside bounds)
bool has_valid_shape_and_values(const QpProblem& problem);

// some inequality row has lb > ub, lb == +inf or ub == -inf: no point can satisfy it
bool has_crossed_bounds(const QpProblem& problem);

// 0.5 x' H x + g' x with the lower triangle of H; scratch must have as many rows as x
double qp_objective(const QpProblem& problem, const Eigen::Ref<const Eigen::VectorXd>& x,
                    Eigen::Ref<Eigen::VectorXd> scratch);

}  // namespace cerebellum::qp
