#include "control/qp/goldfarb_idnani_solver.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

#include <Eigen/Jacobi>

#include "control/qp/cholesky_upper.hpp"

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
    basis_.setZero(n, n);
    triangle_.setZero(n, n);
    for (Eigen::VectorXd* v : {&x_, &normal_, &projected_, &primal_dir_, &dual_dir_, &multipliers_}) {
      v->setZero(n);
    }
    active_.resize(to_size(n));
  }
  if (m_in > capacity_.inequalities) {
    row_values_.setZero(m_in);
    row_scale_.setZero(m_in);
    side_is_active_.resize(to_size(2 * m_in));
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

  // H = U' U, J = U^-1 = L^-T with no constraint active
  if (!cholesky_upper(problem.hessian, settings_.min_pivot_ratio, cholesky_.topLeftCorner(n_, n_))) {
    return QpStatus::NotConvex;
  }
  auto basis = basis_.topLeftCorner(n_, n_);
  invert_upper_triangular(cholesky_.topLeftCorner(n_, n_), basis);

  // unconstrained minimum x = -H^-1 g = -J J' g
  projected_.head(n_).noalias() = basis.transpose() * problem.linear;
  x_.head(n_).noalias() = basis * projected_.head(n_);
  x_.head(n_) *= -1.0;

  // inequality rows are compared by distance, so scale each by 1 / ||C_i||
  const Eigen::Index m_in = dims.inequalities;
  for (Eigen::Index i = 0; i < m_in; ++i) {
    const double norm = problem.ineq_matrix.row(i).norm();
    row_scale_(i) = norm > 0.0 ? 1.0 / norm : 1.0;
  }
  std::fill_n(side_is_active_.begin(), to_size(2 * m_in), char{0});

  const QpStatus equality_status = add_equalities(problem, solution);
  if (equality_status != QpStatus::Solved) return equality_status;

  const int limit = iteration_limit(dims);
  while (true) {
    const Eigen::Index id = most_violated_bound(problem);
    if (id < 0) return QpStatus::Solved;
    double new_multiplier = 0.0;
    // move until bound `id` is met (full step), dropping active bounds that block (partial step)
    while (true) {
      if (solution.iterations >= limit) return QpStatus::MaxIterations;
      ++solution.iterations;
      const double bound = load_constraint(problem, id);
      const double slack = normal_.head(n_).dot(x_.head(n_)) - bound;
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
    const double slack = normal_.head(n_).dot(x_.head(n_)) - bound;
    compute_directions();
    const double free_sq = projected_.segment(q_, n_ - q_).squaredNorm();
    if (!(free_sq > tol_sq * projected_.head(n_).squaredNorm())) {
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
  row_values_.head(m_in).noalias() = problem.ineq_matrix * x_.head(n_);
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

double GoldfarbIdnaniSolver::load_constraint(const QpProblem& problem, Eigen::Index id) {
  // every constraint is written as n' x >= b (equalities as n' x = b)
  if (id < m_eq_) {
    normal_.head(n_) = problem.eq_matrix.row(id).transpose();
    return problem.eq_rhs(id);
  }
  const Eigen::Index row = (id - m_eq_) / 2;
  if ((id - m_eq_) % 2 == 0) {
    normal_.head(n_) = problem.ineq_matrix.row(row).transpose();
    return problem.ineq_lower(row);
  }
  normal_.head(n_) = -problem.ineq_matrix.row(row).transpose();
  return -problem.ineq_upper(row);
}

void GoldfarbIdnaniSolver::compute_directions() {
  const auto basis = basis_.topLeftCorner(n_, n_);
  const Eigen::Index free = n_ - q_;
  // d = J' n_p; primal direction z = J2 d2; dual direction r = R^-1 d1
  projected_.head(n_).noalias() = basis.transpose() * normal_.head(n_);
  if (free > 0) {
    primal_dir_.head(n_).noalias() = basis.rightCols(free) * projected_.segment(q_, free);
  } else {
    primal_dir_.head(n_).setZero();
  }
  dual_dir_.head(q_) = projected_.head(q_);
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
  const double free_sq = projected_.segment(q_, n_ - q_).squaredNorm();
  const double tol = settings_.dependence_tolerance;
  steps.has_primal = free_sq > tol * tol * projected_.head(n_).squaredNorm();
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
  auto basis = basis_.topLeftCorner(n_, n_);
  // rotate d = J' n_p so only its first q + 1 entries remain; J follows the same rotations
  Eigen::JacobiRotation<double> rotation;
  for (Eigen::Index j = n_ - 1; j > q_; --j) {
    if (projected_(j) == 0.0) continue;
    rotation.makeGivens(projected_(j - 1), projected_(j), &projected_(j - 1));
    projected_(j) = 0.0;
    basis.applyOnTheRight(j - 1, j, rotation);
  }
  triangle_.col(q_).head(q_ + 1) = projected_.head(q_ + 1);
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
  // restore the triangle with rotations of neighbouring rows; J takes the same rotations
  auto basis = basis_.topLeftCorner(n_, n_);
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
