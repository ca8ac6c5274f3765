#include "control/qp/goldfarb_idnani_solver.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

#include <Eigen/Jacobi>

#include "control/qp/cholesky_lower.hpp"

namespace cerebellum::qp {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

std::size_t to_size(Eigen::Index i) { return static_cast<std::size_t>(i); }

}  // namespace

GoldfarbIdnaniSolver::GoldfarbIdnaniSolver(const QpDimensions& max_dims, const GoldfarbIdnaniSettings& settings)
    : settings_(settings) {
  reserve(max_dims);
}

void GoldfarbIdnaniSolver::reserve(const QpDimensions& max_dims) {
  // grow only, so a smaller problem never reallocates
  const Eigen::Index n = std::max(max_dims.variables, capacity_.variables);
  const Eigen::Index m_in = std::max(max_dims.inequalities, capacity_.inequalities);
  if (n > capacity_.variables) {
    cholesky_.setZero(n, n);
    ortho_.setZero(n, n);
    triangle_.setZero(n, n);
    for (Eigen::VectorXd* v : {&x_, &normal_, &transformed_, &projected_, &correction_, &residual_, &primal_dir_,
                               &dual_dir_, &multipliers_}) {
      v->setZero(n);
    }
    active_.resize(to_size(n));
  }
  if (m_in > capacity_.inequalities) {
    row_values_.setZero(m_in);
    row_scale_.setZero(m_in);
    side_is_active_.resize(to_size(2 * m_in));
    row_fill_.resize(to_size(m_in));
  }
  if (row_start_.size() < to_size(m_in + 1)) row_start_.resize(to_size(m_in + 1));
  if (n * m_in > static_cast<Eigen::Index>(row_column_.size())) {
    row_column_.resize(to_size(n * m_in));
    row_value_.resize(to_size(n * m_in));
  }
  capacity_ = {n, std::max(max_dims.equalities, capacity_.equalities), m_in};
}

QpStatus GoldfarbIdnaniSolver::solve(const QpProblem& problem, QpSolution& solution) {
  if (reject_invalid_problem(problem, solution)) return solution.status;
  const QpDimensions dims = problem.dimensions();
  reserve(dims);
  solution.reset(dims.variables, dims.equalities, dims.inequalities);
  solution.status = run(problem, solution);
  if (solution.status == QpStatus::Solved || solution.status == QpStatus::MaxIterations) {
    write_result(problem, solution);
  }
  return solution.status;
}

QpStatus GoldfarbIdnaniSolver::run(const QpProblem& problem, QpSolution& solution) {
  const QpDimensions dims = problem.dimensions();
  n_ = dims.variables;
  m_eq_ = dims.equalities;
  q_ = 0;
  if (has_crossed_bounds(problem)) return QpStatus::Infeasible;

  // H = L L'
  auto lower = cholesky_.topLeftCorner(n_, n_);
  if (!cholesky_lower(problem.hessian, settings_.min_pivot_ratio, lower)) return QpStatus::NotConvex;
  // unconstrained minimum x = -H^-1 g = -L^-T L^-1 g, by two triangular solves
  x_.head(n_) = -problem.linear;
  lower.triangularView<Eigen::Lower>().solveInPlace(x_.head(n_));
  lower.triangularView<Eigen::Lower>().transpose().solveInPlace(x_.head(n_));

  // inequality rows are compared by distance, so scale each by 1 / ||C_i||
  const Eigen::Index m_in = dims.inequalities;
  rows_indexed_ = false;
  // column by column: C is column-major
  row_scale_.head(m_in).setZero();
  for (Eigen::Index j = 0; j < n_; ++j) row_scale_.head(m_in) += problem.ineq_matrix.col(j).cwiseAbs2();
  for (Eigen::Index i = 0; i < m_in; ++i) {
    const double norm = std::sqrt(row_scale_(i));
    row_scale_(i) = norm > 0.0 ? 1.0 / norm : 1.0;
  }
  std::fill_n(side_is_active_.begin(), to_size(2 * m_in), char{0});

  const QpStatus equality_status = add_equalities(problem, solution);
  if (equality_status != QpStatus::Solved) return equality_status;

  const int limit = iteration_limit(dims);
  while (true) {
    const Eigen::Index id = most_violated_bound(problem);
    if (id < 0) return QpStatus::Solved;
    index_inequality_rows(problem);
    double new_multiplier = 0.0;
    // move until bound `id` is met (full step), dropping active bounds that block (partial step)
    while (true) {
      if (solution.iterations >= limit) return QpStatus::MaxIterations;
      ++solution.iterations;
      const double bound = load_constraint(problem, id);
      const double slack = normal_dot_x() - bound;
      compute_directions();
      const StepLengths steps = step_lengths(slack);
      if (!steps.has_primal && steps.blocking < 0) return QpStatus::Infeasible;
      if (steps.has_primal && steps.primal <= steps.dual) {
        take_step(steps.primal, true, new_multiplier);
        add_active(id, new_multiplier);
        break;
      }
      take_step(steps.dual, steps.has_primal, new_multiplier);
      drop_active(steps.blocking);
    }
  }
}

QpStatus GoldfarbIdnaniSolver::add_equalities(const QpProblem& problem, QpSolution& solution) {
  const double tol_sq = settings_.dependence_tolerance * settings_.dependence_tolerance;
  for (Eigen::Index k = 0; k < m_eq_; ++k) {
    ++solution.iterations;
    const double bound = load_constraint(problem, k);
    const double slack = normal_dot_x() - bound;
    compute_directions();
    const double free_sq = free_sq_;
    if (!(free_sq > tol_sq * total_sq_)) {
      // a combination of earlier equalities: redundant if it already holds, else contradictory
      const double norm = normal_.head(n_).norm();
      if (std::abs(slack) <= settings_.feasibility_tolerance * std::max(norm, 1.0)) continue;
      return QpStatus::Infeasible;
    }
    double new_multiplier = 0.0;
    take_step(-slack / free_sq, true, new_multiplier);
    add_active(k, new_multiplier);
  }
  return QpStatus::Solved;
}

Eigen::Index GoldfarbIdnaniSolver::most_violated_bound(const QpProblem& problem) {
  const Eigen::Index m_in = problem.ineq_matrix.rows();
  if (m_in == 0) return -1;
  if (rows_indexed_) {
    for (Eigen::Index i = 0; i < m_in; ++i) row_values_(i) = indexed_row_dot_x(i);
  } else {
    // the first check of a solve: indexing the rows costs more than one dense product
    row_values_.head(m_in).noalias() = problem.ineq_matrix * x_.head(n_);
  }
  double worst = -settings_.feasibility_tolerance;
  Eigen::Index worst_id = -1;
  for (Eigen::Index i = 0; i < m_in; ++i) {
    const double lower_gap = (row_values_(i) - problem.ineq_lower(i)) * row_scale_(i);
    if (!side_is_active_[to_size(2 * i)] && lower_gap < worst) {
      worst = lower_gap;
      worst_id = m_eq_ + 2 * i;
    }
    const double upper_gap = (problem.ineq_upper(i) - row_values_(i)) * row_scale_(i);
    if (!side_is_active_[to_size(2 * i + 1)] && upper_gap < worst) {
      worst = upper_gap;
      worst_id = m_eq_ + 2 * i + 1;
    }
  }
  return worst_id;
}

void GoldfarbIdnaniSolver::index_inequality_rows(const QpProblem& problem) {
  // column by column (C is column-major): count each row's nonzeros, then place them
  if (rows_indexed_) return;
  rows_indexed_ = true;
  const Eigen::MatrixXd& c = problem.ineq_matrix;
  const Eigen::Index m_in = c.rows();
  std::fill_n(row_start_.begin(), to_size(m_in + 1), Eigen::Index{0});
  for (Eigen::Index j = 0; j < n_; ++j) {
    for (Eigen::Index i = 0; i < m_in; ++i) {
      if (c(i, j) != 0.0) ++row_start_[to_size(i + 1)];
    }
  }
  for (Eigen::Index i = 0; i < m_in; ++i) {
    row_start_[to_size(i + 1)] += row_start_[to_size(i)];
    row_fill_[to_size(i)] = row_start_[to_size(i)];
  }
  for (Eigen::Index j = 0; j < n_; ++j) {
    for (Eigen::Index i = 0; i < m_in; ++i) {
      if (c(i, j) == 0.0) continue;
      const std::size_t slot = to_size(row_fill_[to_size(i)]++);
      row_column_[slot] = j;
      row_value_[slot] = c(i, j);
    }
  }
}

double GoldfarbIdnaniSolver::load_constraint(const QpProblem& problem, Eigen::Index id) {
  // every constraint is written as n' x >= b (equalities as n' x = b)
  if (id < m_eq_) {
    normal_row_ = -1;
    normal_.head(n_) = problem.eq_matrix.row(id).transpose();
    return problem.eq_rhs(id);
  }
  normal_row_ = (id - m_eq_) / 2;
  if ((id - m_eq_) % 2 == 0) {
    normal_sign_ = 1.0;
    return problem.ineq_lower(normal_row_);
  }
  normal_sign_ = -1.0;
  return -problem.ineq_upper(normal_row_);
}

double GoldfarbIdnaniSolver::indexed_row_dot_x(Eigen::Index row) const {
  double value = 0.0;
  for (Eigen::Index k = row_start_[to_size(row)]; k < row_start_[to_size(row + 1)]; ++k) {
    value += row_value_[to_size(k)] * x_(row_column_[to_size(k)]);
  }
  return value;
}

double GoldfarbIdnaniSolver::normal_dot_x() const {
  if (normal_row_ < 0) return normal_.head(n_).dot(x_.head(n_));
  return normal_sign_ * indexed_row_dot_x(normal_row_);
}

void GoldfarbIdnaniSolver::compute_directions() {
  const auto lower = cholesky_.topLeftCorner(n_, n_);
  // w = L^-1 n_p. L is lower triangular, so w is zero above the normal's first nonzero and the
  // solve starts there
  auto w = transformed_.head(n_);
  Eigen::Index first = 0;
  if (normal_row_ < 0) {
    w = normal_.head(n_);
  } else {
    w.setZero();
    first = n_;
    for (Eigen::Index k = row_start_[to_size(normal_row_)]; k < row_start_[to_size(normal_row_ + 1)]; ++k) {
      const Eigen::Index column = row_column_[to_size(k)];
      w(column) = normal_sign_ * row_value_[to_size(k)];
      first = std::min(first, column);
    }
  }
  if (first < n_) {
    const Eigen::Index tail = n_ - first;
    lower.bottomRightCorner(tail, tail).triangularView<Eigen::Lower>().solveInPlace(w.tail(tail));
  }
  total_sq_ = w.squaredNorm();
  // d1 = Q1' w and the rest r = w - Q1 d1, projected twice so r stays orthogonal to Q1
  auto r = residual_.head(n_);
  r = w;
  auto d1 = projected_.head(q_);
  if (q_ > 0) {
    const auto q1 = ortho_.topLeftCorner(n_, q_);
    d1.noalias() = q1.transpose() * r;
    r.noalias() -= q1 * d1;
    auto again = correction_.head(q_);
    again.noalias() = q1.transpose() * r;
    r.noalias() -= q1 * again;
    d1 += again;
  }
  free_sq_ = r.squaredNorm();
  // primal direction z = L^-T r; dual direction r = R^-1 d1
  primal_dir_.head(n_) = r;
  lower.triangularView<Eigen::Lower>().transpose().solveInPlace(primal_dir_.head(n_));
  dual_dir_.head(q_) = d1;
  triangle_.topLeftCorner(q_, q_).triangularView<Eigen::Upper>().solveInPlace(dual_dir_.head(q_));
}

GoldfarbIdnaniSolver::StepLengths GoldfarbIdnaniSolver::step_lengths(double slack) const {
  StepLengths steps;
  // dual (partial) step: first active inequality whose multiplier reaches zero
  steps.dual = kInf;
  for (Eigen::Index j = 0; j < q_; ++j) {
    if (active_[to_size(j)] < m_eq_ || !(dual_dir_(j) > 0.0)) continue;
    const double ratio = std::max(multipliers_(j), 0.0) / dual_dir_(j);
    if (ratio < steps.dual) {
      steps.dual = ratio;
      steps.blocking = j;
    }
  }
  // primal (full) step: z' n_p = |d2|^2, zero when n_p lies in the span of the active normals
  const double free_sq = free_sq_;
  const double tol = settings_.dependence_tolerance;
  steps.has_primal = free_sq > tol * tol * total_sq_;
  // never backwards: a bound that rounding already nudged to feasibility is added in place
  if (steps.has_primal) steps.primal = std::max(-slack / free_sq, 0.0);
  return steps;
}

void GoldfarbIdnaniSolver::take_step(double step, bool move_primal, double& new_multiplier) {
  if (move_primal) x_.head(n_) += step * primal_dir_.head(n_);
  multipliers_.head(q_) -= step * dual_dir_.head(q_);
  new_multiplier += step;
}

void GoldfarbIdnaniSolver::add_active(Eigen::Index id, double multiplier) {
  // the new normal's part outside the active span extends Q1; R gains the column [d1; |d2|].
  // Callers add only normals with |d2| > 0 (step_lengths' has_primal, add_equalities' test)
  const double free_norm = std::sqrt(free_sq_);
  ortho_.col(q_).head(n_) = residual_.head(n_) / free_norm;
  triangle_.col(q_).head(q_) = projected_.head(q_);
  triangle_(q_, q_) = free_norm;
  active_[to_size(q_)] = id;
  multipliers_(q_) = multiplier;
  if (id >= m_eq_) side_is_active_[to_size(id - m_eq_)] = 1;
  ++q_;
}

void GoldfarbIdnaniSolver::drop_active(Eigen::Index position) {
  const Eigen::Index id = active_[to_size(position)];
  if (id >= m_eq_) side_is_active_[to_size(id - m_eq_)] = 0;
  // remove column `position` of R; the columns after it gain one subdiagonal entry
  for (Eigen::Index j = position; j + 1 < q_; ++j) {
    active_[to_size(j)] = active_[to_size(j + 1)];
    multipliers_(j) = multipliers_(j + 1);
    triangle_.col(j).head(j + 2) = triangle_.col(j + 1).head(j + 2);
  }
  // restore the triangle with rotations of neighbouring rows; Q1 takes the same rotations
  auto basis = ortho_.topLeftCorner(n_, q_);
  Eigen::JacobiRotation<double> rotation;
  for (Eigen::Index j = position; j + 1 < q_; ++j) {
    rotation.makeGivens(triangle_(j, j), triangle_(j + 1, j), &triangle_(j, j));
    triangle_(j + 1, j) = 0.0;
    const Eigen::Index later_columns = q_ - 2 - j;
    if (later_columns > 0) {
      triangle_.middleCols(j + 1, later_columns).applyOnTheLeft(j, j + 1, rotation.adjoint());
    }
    basis.applyOnTheRight(j, j + 1, rotation);
  }
  --q_;
}

void GoldfarbIdnaniSolver::write_result(const QpProblem& problem, QpSolution& solution) {
  solution.x = x_.head(n_);
  // GI keeps H x + g = sum u_j n_j with n_j = a_k, c_i (lower) or -c_i (upper)
  for (Eigen::Index j = 0; j < q_; ++j) {
    const Eigen::Index id = active_[to_size(j)];
    const double u = multipliers_(j);
    if (id < m_eq_) {
      solution.eq_multipliers(id) = -u;
      continue;
    }
    const Eigen::Index row = (id - m_eq_) / 2;
    const bool at_lower = (id - m_eq_) % 2 == 0;
    solution.ineq_multipliers(row) += at_lower ? -u : u;
    solution.ineq_state[to_size(row)] = at_lower ? RowState::AtLower : RowState::AtUpper;
  }
  if (solution.status == QpStatus::Solved) {
    solution.objective = qp_objective(problem, solution.x, normal_.head(n_));
  }
}

int GoldfarbIdnaniSolver::iteration_limit(const QpDimensions& dims) const {
  if (settings_.max_iterations > 0) return settings_.max_iterations;
  return static_cast<int>(10 * (dims.variables + dims.inequalities) + dims.equalities + 100);
}

}  // namespace cerebellum::qp
