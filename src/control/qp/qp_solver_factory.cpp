#include "control/qp/qp_solver_factory.hpp"

#include "control/qp/alglib_qp_solver.hpp"
#include "control/qp/goldfarb_idnani_solver.hpp"

namespace cerebellum::qp {

std::optional<QpSolverKind> qp_solver_kind_from_name(std::string_view name) {
  if (name == "goldfarb_idnani") return QpSolverKind::GoldfarbIdnani;
  if (name == "alglib") return QpSolverKind::Alglib;
  return std::nullopt;
}

std::unique_ptr<QpSolver> make_qp_solver(QpSolverKind kind, const QpDimensions& max_dims) {
  switch (kind) {
    case QpSolverKind::GoldfarbIdnani: return std::make_unique<GoldfarbIdnaniSolver>(max_dims);
    case QpSolverKind::Alglib: return std::make_unique<AlglibQpSolver>(max_dims);
  }
  return nullptr;
}

}  // namespace cerebellum::qp
