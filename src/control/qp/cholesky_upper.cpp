#include "control/qp/cholesky_upper.hpp"

#include <cmath>

namespace cerebellum::qp {

bool cholesky_upper(const Eigen::MatrixXd& hessian, double min_pivot_ratio, Eigen::Ref<Eigen::MatrixXd> upper) {
  const Eigen::Index n = hessian.rows();
  const double max_diagonal = hessian.diagonal().maxCoeff();
  if (!(max_diagonal > 0.0)) return false;
  const double min_pivot = min_pivot_ratio * max_diagonal;
  // column by column: H(i, j) = U(:, i) . U(:, j) over rows 0..min(i, j)
  for (Eigen::Index j = 0; j < n; ++j) {
    for (Eigen::Index i = 0; i < j; ++i) {
      const double dot = upper.col(i).head(i).dot(upper.col(j).head(i));
      upper(i, j) = (hessian(j, i) - dot) / upper(i, i);
    }
    const double pivot = hessian(j, j) - upper.col(j).head(j).squaredNorm();
    if (!(pivot > min_pivot)) return false;
    upper(j, j) = std::sqrt(pivot);
  }
  return true;
}

void invert_upper_triangular(const Eigen::Ref<const Eigen::MatrixXd>& upper, Eigen::Ref<Eigen::MatrixXd> inverse) {
  const Eigen::Index n = upper.rows();
  inverse.setZero();
  // column j solves U y = e_j by back substitution, sweeping columns of U (contiguous memory)
  for (Eigen::Index j = 0; j < n; ++j) {
    auto y = inverse.col(j);
    y(j) = 1.0;
    for (Eigen::Index k = j; k >= 0; --k) {
      y(k) /= upper(k, k);
      y.head(k) -= y(k) * upper.col(k).head(k);
    }
  }
}

}  // namespace cerebellum::qp
