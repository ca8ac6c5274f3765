// Stance-foot forces that produce a desired body wrench: a small dense QP solved with the
// project's Goldfarb-Idnani solver.
//
//   minimize    (A f - w)' S (A f - w) + alpha |f|^2
//   subject to  |f_x| <= mu f_z,  |f_y| <= mu f_z,  0 <= f_z <= f_z,max   (per loaded foot)
//
// f stacks the ground reaction forces of the loaded feet (world-aligned frame), A maps them to
// the force and the torque about the centre of mass (rows: sum f_i; sum r_i x f_i), w is the
// desired wrench and S weights its six components.
#pragma once

#include <array>

#include <Eigen/Core>

#include "control/qp/goldfarb_idnani_solver.hpp"
#include "control/qp/qp_problem.hpp"
#include "control/qp/qp_solution.hpp"
#include "core/joint_layout.hpp"

namespace cerebellum {

using Vector6d = Eigen::Matrix<double, 6, 1>;

struct ForceDistributionConfig {
  double friction_mu = 0.4;
  double force_z_max_n = 150.0;
  // weights of the wrench residual: force x, y, z (per N^2), torque x, y, z (per (N m)^2)
  Vector6d wrench_weights = (Vector6d() << 1.0, 1.0, 1.0, 20.0, 20.0, 20.0).finished();
  double force_regularization = 1e-4;  // alpha, keeps H positive definite
};

class ForceDistribution {
 public:
  explicit ForceDistribution(const ForceDistributionConfig& config = {});

  // feet_from_com: foot contact points relative to the centre of mass (world-aligned frame);
  // force_z_max_n: per leg, the largest normal force it may carry (<= 0: the leg carries nothing);
  // wrench: desired force (N) and torque about the centre of mass (N m), stacked.
  // Writes one force per leg (zero for unloaded legs) and returns the solver's status; on failure
  // the forces are zero.
  qp::QpStatus solve(const std::array<Eigen::Vector3d, kNumLegs>& feet_from_com,
                     const std::array<double, kNumLegs>& force_z_max_n, const Vector6d& wrench,
                     std::array<Eigen::Vector3d, kNumLegs>& forces);

  const ForceDistributionConfig& config() const { return config_; }
  // the problem and solution of the last solve (for checks and tests)
  const qp::QpProblem& last_problem() const { return problems_[last_slot_]; }
  const qp::QpSolution& last_solution() const { return solutions_[last_slot_]; }
  int loaded_feet() const { return static_cast<int>(last_slot_) + 1; }

 private:
  ForceDistributionConfig config_;
  // one problem and solution per number of loaded feet (1..4): sized once, never resized
  std::array<qp::QpProblem, kNumLegs> problems_;
  std::array<qp::QpSolution, kNumLegs> solutions_;
  qp::GoldfarbIdnaniSolver solver_;
  Eigen::Matrix<double, 6, 12> weighted_map_;  // S^1/2 A for the loaded feet
  std::array<std::size_t, kNumLegs> loaded_legs_{};
  std::size_t last_slot_ = 0;
};

}  // namespace cerebellum
