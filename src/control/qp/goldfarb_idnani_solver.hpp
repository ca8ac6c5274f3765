// Dense dual active-set QP solver after Goldfarb & Idnani (1983).
//
// Starts at the unconstrained minimum -H^-1 g, adds the equality rows, then repeatedly picks the
// most violated inequality bound and moves primal and dual variables until it is satisfied,
// dropping active bounds whose multipliers would change sign. The active set is kept as
// J = L^-T Q and the triangle R of the QR factorisation of L^-1 N (H = L L', N the active
// normals), both updated by Givens rotations. All workspace is sized by reserve(); solving
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
  // loads normal_ and the bound for a constraint id, returns the bound
  double load_constraint(const QpProblem& problem, Eigen::Index id);
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

  Eigen::MatrixXd cholesky_;  // U with H = U' U
  Eigen::MatrixXd basis_;     // J (n x n)
  Eigen::MatrixXd triangle_;  // R (q x q used)
  Eigen::VectorXd x_;
  Eigen::VectorXd normal_;       // n_p, normal of the constraint being added
  Eigen::VectorXd projected_;    // d = J' n_p
  Eigen::VectorXd primal_dir_;   // z = J2 d2
  Eigen::VectorXd dual_dir_;     // r = R^-1 d1
  Eigen::VectorXd multipliers_;  // u of the active constraints, in active order
  Eigen::VectorXd row_values_;   // C x
  Eigen::VectorXd row_scale_;    // 1 / ||C_i|| (1 for zero rows)
  // constraint ids: equality k -> k; inequality row i -> m_eq + 2 i (lower) or m_eq + 2 i + 1
  // (upper)
  std::vector<Eigen::Index> active_;
  std::vector<char> side_is_active_;  // per inequality side, indexed by 2 i + side
};

}  // namespace cerebellum::qp
