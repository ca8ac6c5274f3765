#include "control/force_distribution.hpp"

#include <cmath>
#include <limits>

namespace cerebellum {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

Eigen::Matrix3d cross_matrix(const Eigen::Vector3d& v) {
  Eigen::Matrix3d m;
  m << 0.0, -v.z(), v.y(), v.z(), 0.0, -v.x(), -v.y(), v.x(), 0.0;
  return m;
}

}  // namespace

ForceDistribution::ForceDistribution(const ForceDistributionConfig& config)
    : config_(config), solver_(qp::QpDimensions{12, 0, 20}) {
  // friction pyramid and normal-force rows do not depend on the feet: written once per size
  for (std::size_t slot = 0; slot < kNumLegs; ++slot) {
    const Eigen::Index feet = static_cast<Eigen::Index>(slot) + 1;
    qp::QpProblem& problem = problems_[slot];
    problem.resize({3 * feet, 0, 5 * feet});
    for (Eigen::Index j = 0; j < feet; ++j) {
      const Eigen::Index c = 3 * j;
      const Eigen::Index r = 5 * j;
      const double mu = config_.friction_mu;
      problem.ineq_matrix.block<5, 3>(r, c) << 1.0, 0.0, -mu,  //  f_x - mu f_z <= 0
          1.0, 0.0, mu,                                        //  f_x + mu f_z >= 0
          0.0, 1.0, -mu,                                       //  f_y - mu f_z <= 0
          0.0, 1.0, mu,                                        //  f_y + mu f_z >= 0
          0.0, 0.0, 1.0;                                       //  0 <= f_z <= max
      problem.ineq_lower.segment<5>(r) << -kInf, 0.0, -kInf, 0.0, 0.0;
      problem.ineq_upper.segment<5>(r) << 0.0, kInf, 0.0, kInf, config_.force_z_max_n;
    }
    solutions_[slot].reset(3 * feet, 0, 5 * feet);
  }
  weighted_map_.setZero();
}

qp::QpStatus ForceDistribution::solve(const std::array<Eigen::Vector3d, kNumLegs>& feet_from_com,
                                      const std::array<double, kNumLegs>& force_z_max_n, const Vector6d& wrench,
                                      std::array<Eigen::Vector3d, kNumLegs>& forces) {
  for (Eigen::Vector3d& f : forces) f.setZero();
  std::size_t count = 0;
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
    if (force_z_max_n[leg] > 0.0) loaded_legs_[count++] = leg;
  }
  if (count == 0) return qp::QpStatus::Infeasible;
  last_slot_ = count - 1;
  qp::QpProblem& problem = problems_[last_slot_];
  qp::QpSolution& solution = solutions_[last_slot_];
  const Eigen::Index n = static_cast<Eigen::Index>(3 * count);

  // S^1/2 A: force rows sum the feet, torque rows r_i x f_i
  const Vector6d sqrt_weights = config_.wrench_weights.cwiseSqrt();
  for (std::size_t j = 0; j < count; ++j) {
    const Eigen::Index c = static_cast<Eigen::Index>(3 * j);
    weighted_map_.block<3, 3>(0, c) = sqrt_weights.head<3>().asDiagonal() * Eigen::Matrix3d::Identity();
    weighted_map_.block<3, 3>(3, c) =
        sqrt_weights.tail<3>().asDiagonal() * cross_matrix(feet_from_com[loaded_legs_[j]]);
    problem.ineq_upper(static_cast<Eigen::Index>(5 * j + 4)) =
        std::min(force_z_max_n[loaded_legs_[j]], config_.force_z_max_n);
  }
  const auto map = weighted_map_.leftCols(n);
  // 0.5 f' H f + g' f with H = 2 (A' S A + alpha I), g = -2 A' S w
  problem.hessian.noalias() = 2.0 * map.transpose() * map;
  problem.hessian.diagonal().array() += 2.0 * config_.force_regularization;
  problem.linear.noalias() = -2.0 * map.transpose() * sqrt_weights.cwiseProduct(wrench);

  const qp::QpStatus status = solver_.solve(problem, solution);
  if (status != qp::QpStatus::Solved) return status;
  for (std::size_t j = 0; j < count; ++j)
    forces[loaded_legs_[j]] = solution.x.segment<3>(static_cast<Eigen::Index>(3 * j));
  return status;
}

}  // namespace cerebellum
