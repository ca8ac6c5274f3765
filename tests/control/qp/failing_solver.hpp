// A QP solver that always fails, to prove that its users notice.
#pragma once

#include <string_view>

#include "control/qp/qp_solver.hpp"

namespace cerebellum::testing {

class FailingSolver final : public qp::QpSolver {
 public:
  qp::QpStatus solve(const qp::QpProblem&, qp::QpSolution& solution) override {
    solution.status = qp::QpStatus::Infeasible;
    return solution.status;
  }
  std::string_view name() const override { return "failing"; }
};

}  // namespace cerebellum::testing
