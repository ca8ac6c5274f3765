// Builds a QpSolver from a configuration name ("goldfarb_idnani" or "alglib").
#pragma once

#include <memory>
#include <optional>
#include <string_view>

#include "control/qp/qp_problem.hpp"
#include "control/qp/qp_solver.hpp"

namespace cerebellum::qp {

enum class QpSolverKind { GoldfarbIdnani, Alglib };

std::optional<QpSolverKind> qp_solver_kind_from_name(std::string_view name);

// workspace is sized for problems up to max_dims (larger problems grow it on demand)
std::unique_ptr<QpSolver> make_qp_solver(QpSolverKind kind, const QpDimensions& max_dims);

}  // namespace cerebellum::qp
