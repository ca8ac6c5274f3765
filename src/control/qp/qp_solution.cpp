#include "control/qp/qp_solution.hpp"

#include <cstddef>
#include <limits>

namespace cerebellum::qp {

std::string_view to_string(QpStatus status) {
  switch (status) {
    case QpStatus::Solved: return "solved";
    case QpStatus::Infeasible: return "infeasible";
    case QpStatus::NotConvex: return "not convex";
    case QpStatus::InvalidInput: return "invalid input";
    case QpStatus::MaxIterations: return "max iterations";
  }
  return "unknown";
}

void QpSolution::reset(Eigen::Index variables, Eigen::Index equalities, Eigen::Index inequalities) {
  x.setZero(variables);
  objective = std::numeric_limits<double>::quiet_NaN();
  iterations = 0;
  eq_multipliers.setZero(equalities);
  ineq_multipliers.setZero(inequalities);
  ineq_state.assign(static_cast<std::size_t>(inequalities), RowState::Inactive);
}

bool reject_invalid_problem(const QpProblem& problem, QpSolution& solution) {
  if (has_valid_shape_and_values(problem)) return false;
  solution.status = QpStatus::InvalidInput;
  solution.iterations = 0;
  solution.objective = std::numeric_limits<double>::quiet_NaN();
  return true;
}

}  // namespace cerebellum::qp
