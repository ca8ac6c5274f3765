#include "control/qp/alglib_qp_solver.hpp"

#include <cstddef>
#include <limits>

#include <optimization.h>

#include "control/qp/cholesky_lower.hpp"

namespace cerebellum::qp {

struct AlglibQpSolver::Workspace {
  alglib::ae_int_t state_variables = -1;  // size minqp `state` was created for
  alglib::minqpstate state;
  alglib::minqpreport report;
  alglib::real_2d_array quadratic;
  alglib::real_1d_array linear;
  alglib::real_2d_array rows;  // [A_eq; C]
  alglib::real_1d_array lower;
  alglib::real_1d_array upper;
  alglib::real_1d_array x;
  Eigen::MatrixXd cholesky;
  Eigen::VectorXd scratch;
};

namespace {

// ALGLIB completion codes (see minqpresults): > 0 success, 5 iteration limit, 7 best point
// when the tolerance cannot be reached; -2/-3 infeasible; -4/-9 not convex.
QpStatus status_from_termination(alglib::ae_int_t code) {
  if (code == 5) return QpStatus::MaxIterations;
  if (code > 0) return QpStatus::Solved;
  if (code == -2 || code == -3) return QpStatus::Infeasible;
  if (code == -4 || code == -9) return QpStatus::NotConvex;
  return QpStatus::InvalidInput;
}

}  // namespace

AlglibQpSolver::AlglibQpSolver(const QpDimensions& max_dims, const AlglibQpSettings& settings)
    : settings_(settings), workspace_(std::make_unique<Workspace>()) {
  workspace_->cholesky.setZero(max_dims.variables, max_dims.variables);
  workspace_->scratch.setZero(max_dims.variables);
}

AlglibQpSolver::~AlglibQpSolver() = default;

QpStatus AlglibQpSolver::solve(const QpProblem& problem, QpSolution& solution) {
  if (reject_invalid_problem(problem, solution)) return solution.status;
  const QpDimensions dims = problem.dimensions();
  solution.reset(dims.variables, dims.equalities, dims.inequalities);
  solution.status = run(problem, solution);
  return solution.status;
}

QpStatus AlglibQpSolver::run(const QpProblem& problem, QpSolution& solution) {
  const QpDimensions dims = problem.dimensions();
  const Eigen::Index n = dims.variables;
  const Eigen::Index m_eq = dims.equalities;
  const Eigen::Index m = dims.equalities + dims.inequalities;
  if (has_crossed_bounds(problem)) return QpStatus::Infeasible;

  // DENSE-IPM may stall or throw on an indefinite H, so check convexity first
  Workspace& ws = *workspace_;
  if (ws.cholesky.rows() < n) ws.cholesky.setZero(n, n);
  if (ws.scratch.size() < n) ws.scratch.setZero(n);
  if (!cholesky_lower(problem.hessian, settings_.min_pivot_ratio, ws.cholesky.topLeftCorner(n, n))) {
    return QpStatus::NotConvex;
  }

  // copy into ALGLIB arrays: equalities become rows with equal lower and upper bounds
  ws.quadratic.setlength(n, n);
  ws.linear.setlength(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    ws.linear[i] = problem.linear(i);
    for (Eigen::Index j = 0; j <= i; ++j) ws.quadratic(i, j) = problem.hessian(i, j);
  }
  ws.rows.setlength(m, n);
  ws.lower.setlength(m);
  ws.upper.setlength(m);
  for (Eigen::Index k = 0; k < m_eq; ++k) {
    for (Eigen::Index j = 0; j < n; ++j) ws.rows(k, j) = problem.eq_matrix(k, j);
    ws.lower[k] = problem.eq_rhs(k);
    ws.upper[k] = problem.eq_rhs(k);
  }
  for (Eigen::Index i = 0; i < dims.inequalities; ++i) {
    for (Eigen::Index j = 0; j < n; ++j) ws.rows(m_eq + i, j) = problem.ineq_matrix(i, j);
    ws.lower[m_eq + i] = problem.ineq_lower(i);
    ws.upper[m_eq + i] = problem.ineq_upper(i);
  }

  try {
    if (ws.state_variables != n) {
      alglib::minqpcreate(n, ws.state);
      ws.state_variables = n;
    }
    alglib::minqpsetquadraticterm(ws.state, ws.quadratic, false);
    alglib::minqpsetlinearterm(ws.state, ws.linear);
    alglib::minqpsetlc2dense(ws.state, ws.rows, ws.lower, ws.upper, m);
    alglib::minqpsetscaleautodiag(ws.state);
    alglib::minqpsetalgodenseipm(ws.state, settings_.ipm_tolerance);
    alglib::minqpoptimize(ws.state);
    alglib::minqpresults(ws.state, ws.x, ws.report);
  } catch (const alglib::ap_error&) {
    // inputs are already checked, so an ALGLIB error means its factorisation broke down
    ws.state_variables = -1;
    return QpStatus::NotConvex;
  }

  solution.iterations = static_cast<int>(ws.report.outeriterationscount + ws.report.inneriterationscount);
  const QpStatus status = status_from_termination(ws.report.terminationtype);
  if (status != QpStatus::Solved && status != QpStatus::MaxIterations) return status;

  for (Eigen::Index j = 0; j < n; ++j) solution.x(j) = ws.x[j];
  // ALGLIB's convention matches QpSolution: g + H x + sum(row_k * laglc_k) = 0
  for (Eigen::Index k = 0; k < m_eq; ++k) solution.eq_multipliers(k) = ws.report.laglc[k];
  for (Eigen::Index i = 0; i < dims.inequalities; ++i) {
    const double multiplier = ws.report.laglc[m_eq + i];
    solution.ineq_multipliers(i) = multiplier;
    RowState& state = solution.ineq_state[static_cast<std::size_t>(i)];
    if (multiplier > settings_.active_multiplier_threshold) state = RowState::AtUpper;
    if (multiplier < -settings_.active_multiplier_threshold) state = RowState::AtLower;
  }
  if (status == QpStatus::Solved) {
    solution.objective = qp_objective(problem, solution.x, ws.scratch.head(n));
  }
  return status;
}

}  // namespace cerebellum::qp
