// Dense dual active-set QP solver after Goldfarb & Idnani (1983).
//
// Starts at the unconstrained minimum -H^-1 g, adds the equality rows, then repeatedly picks the
// most violated inequality bound and moves primal and dual variables until it is satisfied,
// dropping active bounds whose multipliers would change sign.
//
// The active set is kept in range-space form: with H = L L' and N the active normals,
// L^-1 N = Q1 R, Q1 orthonormal (n x q, classical Gram-Schmidt with one reorthogonalisation) and
// R upper triangular; dropping a normal restores R with Givens rotations that Q1 takes too. This
// is the paper's J = L^-T [Q1 Q2] without ever forming L^-1 or Q2: a new normal costs two
// triangular solves and four products with Q1 (about 2 n^2 + 4 n q), where the explicit J costs
// an inverse (n^3 / 3) per solve and 4 n (n - q) per normal. The trot's MPC problems have none or
// one or two bounds active at their minimum. The inequality rows are read through their nonzeros
// (the MPC's rows hold one or two of 60-120 entries). All workspace is sized by reserve(); solving
// problems no larger than the reservation does not allocate.
#pragma once

#include <string_view>
#include <vector>

#include <Eigen/Core>

#include "control/qp/qp_solver.hpp"

namespace cerebellum::qp {

struct GoldfarbIdnaniSettings {
  // 0 selects 10 * (variables + inequalities) + equalities + 100
  int max_iterations = 0;
  // a bound counts as violated when it is missed by more than this distance (row-normalised)
  double feasibility_tolerance = 1e-9;
  // H is rejected as not convex when a Cholesky pivot <= this ratio times max(diag(H))
  double min_pivot_ratio = 1e-13;
  // a new normal whose part outside the active span is below this fraction counts as dependent
  double dependence_tolerance = 1e-12;
};

class GoldfarbIdnaniSolver final : public QpSolver {
 public:
  explicit GoldfarbIdnaniSolver(const QpDimensions& max_dims = {}, const GoldfarbIdnaniSettings& settings = {});

  // sizes the workspace for problems up to these dimensions
  void reserve(const QpDimensions& max_dims);

  QpStatus solve(const QpProblem& problem, QpSolution& solution) override;
  std::string_view name() const override { return "goldfarb_idnani"; }

 private:
  // result of computing the step for one constraint normal
  struct StepLengths {
    double dual = 0.0;           // largest step keeping active inequality multipliers >= 0
    Eigen::Index blocking = -1;  // active position limiting the dual step (-1: none)
    double primal = 0.0;         // step that makes the new constraint exactly active
    bool has_primal = false;     // false when the normal depends on the active normals
  };

  QpStatus run(const QpProblem& problem, QpSolution& solution);
  QpStatus add_equalities(const QpProblem& problem, QpSolution& solution);
  // returns the inequality side id that is violated most, or -1 when none is
  Eigen::Index most_violated_bound(const QpProblem& problem);
  // lists the nonzeros of the inequality rows (row_start_, row_column_, row_value_), once per
  // solve, before the first inequality is added
  void index_inequality_rows(const QpProblem& problem);
  // selects the normal and the bound of a constraint id, returns the bound
  double load_constraint(const QpProblem& problem, Eigen::Index id);
  // C_row x through the row's indexed nonzeros
  double indexed_row_dot_x(Eigen::Index row) const;
  // n_p' x of the selected normal
  double normal_dot_x() const;
  void compute_directions();
  StepLengths step_lengths(double slack) const;
  // x += step z (when move_primal), u -= step r, new constraint's multiplier += step
  void take_step(double step, bool move_primal, double& new_multiplier);
  void add_active(Eigen::Index id, double multiplier);
  void drop_active(Eigen::Index position);
  void write_result(const QpProblem& problem, QpSolution& solution);
  int iteration_limit(const QpDimensions& dims) const;

  GoldfarbIdnaniSettings settings_;
  QpDimensions capacity_;
  Eigen::Index n_ = 0;     // variables of the current problem
  Eigen::Index m_eq_ = 0;  // equality rows of the current problem
  Eigen::Index q_ = 0;     // number of active constraints

  Eigen::MatrixXd cholesky_;  // L with H = L L' (lower triangle)
  Eigen::MatrixXd ortho_;     // Q1 (n x q used), orthonormal: L^-1 N = Q1 R
  Eigen::MatrixXd triangle_;  // R (q x q used)
  Eigen::VectorXd x_;
  Eigen::VectorXd normal_;       // n_p of an equality being added (dense); scratch otherwise
  // the normal of an inequality being added: sign times inequality row normal_row_ (-1: an
  // equality, held in normal_)
  Eigen::Index normal_row_ = -1;
  double normal_sign_ = 1.0;
  Eigen::VectorXd transformed_;  // w = L^-1 n_p
  Eigen::VectorXd projected_;    // d1 = Q1' w (q used)
  Eigen::VectorXd correction_;   // the reorthogonalisation's Q1' (w - Q1 d1) (q used)
  Eigen::VectorXd residual_;     // w - Q1 d1: the part of w outside the active span (Q2 d2)
  Eigen::VectorXd primal_dir_;   // z = L^-T (w - Q1 d1), the paper's J2 d2
  Eigen::VectorXd dual_dir_;     // r = R^-1 d1
  double total_sq_ = 0.0;        // |w|^2 = |d|^2
  double free_sq_ = 0.0;         // |w - Q1 d1|^2 = |d2|^2
  Eigen::VectorXd multipliers_;  // u of the active constraints, in active order
  Eigen::VectorXd row_values_;   // C x
  Eigen::VectorXd row_scale_;    // 1 / ||C_i|| (1 for zero rows)
  // nonzeros of C row by row: row i holds row_column_ / row_value_ [row_start_[i], row_start_[i + 1])
  bool rows_indexed_ = false;
  std::vector<Eigen::Index> row_start_;
  std::vector<Eigen::Index> row_fill_;  // scratch while indexing
  std::vector<Eigen::Index> row_column_;
  std::vector<double> row_value_;
  // constraint ids: equality k -> k; inequality row i -> m_eq + 2 i (lower) or m_eq + 2 i + 1
  // (upper)
  std::vector<Eigen::Index> active_;
  std::vector<char> side_is_active_;  // per inequality side, indexed by 2 i + side
};

}  // namespace cerebellum::qp
