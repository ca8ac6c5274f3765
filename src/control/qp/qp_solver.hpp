// One interface for every dense QP solver, so a controller can pick one by configuration.
#pragma once

#include <string_view>

#include "control/qp/qp_problem.hpp"
#include "control/qp/qp_solution.hpp"

namespace cerebellum::qp {

class QpSolver {
 public:
  virtual ~QpSolver() = default;
  // solves the problem into solution (reusing its storage) and returns solution.status
  virtual QpStatus solve(const QpProblem& problem, QpSolution& solution) = 0;
  virtual std::string_view name() const = 0;
};

}  // namespace cerebellum::qp
