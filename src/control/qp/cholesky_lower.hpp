// Allocation-free dense Cholesky H = L L' (L lower triangular).
#pragma once

#include <Eigen/Core>

namespace cerebellum::qp {

// factors the lower triangle of the square matrix H into the lower triangle of `lower` (same
// size as H; its strict upper triangle is left untouched). Returns false when H is not
// numerically positive definite: some pivot <= min_pivot_ratio * max(diag(H)).
bool cholesky_lower(const Eigen::MatrixXd& hessian, double min_pivot_ratio, Eigen::Ref<Eigen::MatrixXd> lower);

}  // namespace cerebellum::qp
