// QpSolver on top of ALGLIB's minqp, used as a reference and as a fallback solver.
//
// ALGLIB offers BLEIC, DENSE-AUL and DENSE-IPM for dense linearly constrained QPs. This uses
// DENSE-IPM: for convex problems it is the one ALGLIB recommends, converges in a nearly
// size-independent number of iterations, returns precise Lagrange multipliers, and needs no
// feasible starting point (BLEIC does, and DENSE-AUL only approximates the multipliers).
// ALGLIB allocates inside every solve; the ALGLIB headers stay out of this header.
#pragma once

#include <memory>
#include <string_view>

#include "control/qp/qp_solver.hpp"

namespace cerebellum::qp {

struct AlglibQpSettings {
  // DENSE-IPM stops when primal and dual infeasibility and the duality gap fall below this
  double ipm_tolerance = 1e-12;
  // H is rejected as not convex when a Cholesky pivot <= this ratio times max(diag(H))
  double min_pivot_ratio = 1e-13;
  // an inequality row is reported active when |multiplier| exceeds this
  double active_multiplier_threshold = 1e-8;
};

class AlglibQpSolver final : public QpSolver {
 public:
  explicit AlglibQpSolver(const QpDimensions& max_dims = {}, const AlglibQpSettings& settings = {});
  ~AlglibQpSolver() override;
  AlglibQpSolver(const AlglibQpSolver&) = delete;
  AlglibQpSolver& operator=(const AlglibQpSolver&) = delete;

  QpStatus solve(const QpProblem& problem, QpSolution& solution) override;
  std::string_view name() const override { return "alglib"; }

 private:
  struct Workspace;
  QpStatus run(const QpProblem& problem, QpSolution& solution);

  AlglibQpSettings settings_;
  std::unique_ptr<Workspace> workspace_;
};

}  // namespace cerebellum::qp
