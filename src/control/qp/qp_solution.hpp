// Result of a QP solve: status, minimizer, objective, multipliers and active inequality rows.
//
// Multipliers follow one sign convention for every solver; at a solution
//   H x + g + A_eq' eq_multipliers + C' ineq_multipliers = 0
// with ineq_multipliers(i) >= 0 when row i sits at its upper bound, <= 0 at its lower bound,
// and 0 when the row is inactive.
#pragma once

#include <cstdint>
#include <limits>
#include <string_view>
#include <vector>

#include <Eigen/Core>

#include "control/qp/qp_problem.hpp"

namespace cerebellum::qp {

enum class QpStatus : std::uint8_t {
  Solved,
  Infeasible,     // no point satisfies the constraints
  NotConvex,      // H is not (numerically) positive definite
  InvalidInput,   // size mismatch, no variables, NaN or inf where values must be finite
  MaxIterations,  // iteration limit reached; x is the last iterate
};

std::string_view to_string(QpStatus status);

enum class RowState : std::uint8_t { Inactive, AtLower, AtUpper };

struct QpSolution {
  QpStatus status = QpStatus::InvalidInput;
  // x, objective and multipliers are meaningful only when status == Solved
  Eigen::VectorXd x;
  double objective = std::numeric_limits<double>::quiet_NaN();
  int iterations = 0;
  Eigen::VectorXd eq_multipliers;    // one per equality row
  Eigen::VectorXd ineq_multipliers;  // one per inequality row
  std::vector<RowState> ineq_state;  // active set: which bound each inequality row sits on

  // sizes the members for a problem (no allocation when the sizes are unchanged), clears values
  void reset(Eigen::Index variables, Eigen::Index equalities, Eigen::Index inequalities);
};

// marks solution InvalidInput (no iterations, NaN objective) and returns true when the problem
// fails has_valid_shape_and_values; the first step of every solver
bool reject_invalid_problem(const QpProblem& problem, QpSolution& solution);

}  // namespace cerebellum::qp
