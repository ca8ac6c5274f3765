// Allocation-free dense Cholesky H = U' U (U upper triangular) and the inverse of U.
#pragma once

#include <Eigen/Core>

namespace cerebellum::qp {

// factors the lower triangle of the square matrix H into the upper triangle of `upper`
// (same size as H; its strict lower triangle is left untouched). Returns false when H is not
// numerically positive definite: some pivot <= min_pivot_ratio * max(diag(H)).
bool cholesky_upper(const Eigen::MatrixXd& hessian, double min_pivot_ratio, Eigen::Ref<Eigen::MatrixXd> upper);

// inverse = U^-1 (upper triangular, strict lower triangle zeroed), so inverse * inverse' = H^-1
void invert_upper_triangular(const Eigen::Ref<const Eigen::MatrixXd>& upper, Eigen::Ref<Eigen::MatrixXd> inverse);

}  // namespace cerebellum::qp
