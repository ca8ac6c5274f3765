#include "control/locomotion/convex_mpc.hpp"

#include <Eigen/Dense>
#include <Eigen/Geometry>
#include <cmath>
#include <limits>
#include <unsupported/Eigen/MatrixFunctions>

#include "control/locomotion/lone_pair.hpp"

namespace cerebellum {
namespace {

constexpr int kInputs = 3 * kNumLegs;
constexpr int kRowsPerFoot = 5;

Eigen::Matrix3d skew(const Eigen::Vector3d& v) {
  Eigen::Matrix3d m;
  m << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
  return m;
}

bool input_is_finite(const MpcInput& input) {
  if (!input.x0.allFinite()) return false;
  for (const auto& x : input.x_ref) {
    if (!x.allFinite()) return false;
  }
  for (const auto& r : input.foot_from_com) {
    if (!r.allFinite()) return false;
  }
  for (const auto& shift : input.com_shift) {
    if (!shift.allFinite()) return false;
  }
  return true;
}

}  // namespace

bool stands_throughout(const std::array<std::array<bool, kNumLegs>, kMpcHorizon>& contact) {
  for (const auto& step : contact) {
    for (const bool down : step) {
      if (!down) return false;
    }
  }
  return true;
}

ConvexMpc::ConvexMpc(const ConvexMpcConfig& config, std::unique_ptr<qp::QpSolver> solver)
    : config_(config), solver_(std::move(solver)) {
  a_qp_.setZero();
  b_qp_.setZero();
  b_kept_.resize(kSrbStates * kMpcHorizon, kInputs * kMpcHorizon);
  weighted_b_.resize(kSrbStates * kMpcHorizon, kInputs * kMpcHorizon);
}

void ConvexMpc::continuous_dynamics(const ConvexMpcConfig& config, double yaw,
                                    const std::array<Eigen::Vector3d, kNumLegs>& foot_from_com,
                                    Eigen::Matrix<double, kSrbStates, kSrbStates>& a,
                                    Eigen::Matrix<double, kSrbStates, kInputs>& b) {
  state_matrix(yaw, a);
  input_matrix(config, yaw, foot_from_com, b);
}

void ConvexMpc::state_matrix(double yaw, Eigen::Matrix<double, kSrbStates, kSrbStates>& a) {
  const Eigen::Matrix3d rz = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  a.setZero();
  a.block<3, 3>(0, 6) = rz.transpose();  // rpy rates from world angular velocity (small roll/pitch)
  a.block<3, 3>(3, 9).setIdentity();     // position from velocity
  a(11, 12) = 1.0;                       // gravity state drives vz
}

void ConvexMpc::input_matrix(const ConvexMpcConfig& config, double yaw,
                             const std::array<Eigen::Vector3d, kNumLegs>& foot_from_com,
                             Eigen::Matrix<double, kSrbStates, kInputs>& b) {
  const Eigen::Matrix3d rz = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  const Eigen::Matrix3d inertia_world = rz * config.inertia_diag.asDiagonal() * rz.transpose();
  const Eigen::Matrix3d inertia_inv = inertia_world.inverse();
  b.setZero();
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
    b.block<3, 3>(6, 3 * leg) = inertia_inv * skew(foot_from_com[leg]);
    b.block<3, 3>(9, 3 * leg) = Eigen::Matrix3d::Identity() / config.mass_kg;
  }
}

void ConvexMpc::zero_order_hold(const Eigen::Matrix<double, kSrbStates, kSrbStates>& a, double dt,
                                Eigen::Matrix<double, kSrbStates, kSrbStates>& ad,
                                Eigen::Matrix<double, kSrbStates, kSrbStates>& hold) {
  // exp([[A, I], [0, 0]] dt) = [[exp(A dt), integral of exp(A s) over [0, dt]], [0, I]]
  Eigen::Matrix<double, 2 * kSrbStates, 2 * kSrbStates> augmented;
  augmented.setZero();
  augmented.topLeftCorner<kSrbStates, kSrbStates>() = a * dt;
  augmented.topRightCorner<kSrbStates, kSrbStates>().diagonal().setConstant(dt);
  const Eigen::Matrix<double, 2 * kSrbStates, 2 * kSrbStates> exponential = augmented.exp();
  ad = exponential.topLeftCorner<kSrbStates, kSrbStates>();
  hold = exponential.topRightCorner<kSrbStates, kSrbStates>();
}

void ConvexMpc::discretize(const Eigen::Matrix<double, kSrbStates, kSrbStates>& a,
                           const Eigen::Matrix<double, kSrbStates, kInputs>& b, double dt,
                           Eigen::Matrix<double, kSrbStates, kSrbStates>& ad,
                           Eigen::Matrix<double, kSrbStates, kInputs>& bd) {
  Eigen::Matrix<double, kSrbStates, kSrbStates> hold;
  zero_order_hold(a, dt, ad, hold);
  bd = hold * b;
}

void ConvexMpc::build(const MpcInput& input) {
  // discrete dynamics at the current yaw; the feet's lever arms follow the COM along the horizon
  Eigen::Matrix<double, kSrbStates, kSrbStates> a, ad, hold;
  Eigen::Matrix<double, kSrbStates, kInputs> b;
  state_matrix(input.x0[2], a);
  zero_order_hold(a, config_.dt_s, ad, hold);
  std::array<Eigen::Matrix<double, kSrbStates, kInputs>, kMpcHorizon> bd;
  std::array<Eigen::Vector3d, kNumLegs> lever;
  for (int k = 0; k < kMpcHorizon; ++k) {
    for (std::size_t leg = 0; leg < kNumLegs; ++leg) lever[leg] = input.foot_from_com[leg] - input.com_shift[k];
    input_matrix(config_, input.x0[2], lever, b);
    bd[k].noalias() = hold * b;
  }

  // condensed prediction: block (i, j) of Bqp = Ad^(i-j) Bd_j for j <= i
  a_qp_.block<kSrbStates, kSrbStates>(0, 0) = ad;
  for (int i = 1; i < kMpcHorizon; ++i) {
    a_qp_.block<kSrbStates, kSrbStates>(kSrbStates * i, 0).noalias() =
        ad * a_qp_.block<kSrbStates, kSrbStates>(kSrbStates * (i - 1), 0);
  }
  for (int j = 0; j < kMpcHorizon; ++j) {
    b_qp_.block<kSrbStates, kInputs>(kSrbStates * j, kInputs * j) = bd[j];
    for (int i = j + 1; i < kMpcHorizon; ++i) {
      b_qp_.block<kSrbStates, kInputs>(kSrbStates * i, kInputs * j).noalias() =
          ad * b_qp_.block<kSrbStates, kInputs>(kSrbStates * (i - 1), kInputs * j);
    }
  }

  // keep the force variables of feet in stance
  kept_count_ = 0;
  for (int k = 0; k < kMpcHorizon; ++k) {
    for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
      if (!input.contact[k][leg]) continue;
      for (int axis = 0; axis < 3; ++axis) kept_[kept_count_++] = kInputs * k + 3 * static_cast<int>(leg) + axis;
    }
  }
  const int n = kept_count_;
  for (int v = 0; v < n; ++v) b_kept_.col(v) = b_qp_.col(kept_[v]);

  // weights: L on every predicted state, alpha on every force
  Eigen::Matrix<double, kSrbStates * kMpcHorizon, 1> weights;
  for (int k = 0; k < kMpcHorizon; ++k) {
    for (int s = 0; s < 12; ++s) weights[kSrbStates * k + s] = config_.state_weights[s];
    if (input.hold_position) weights[kSrbStates * k + 3] = weights[kSrbStates * k + 4] = config_.stand_position_weight;
    if (lone_pair(input.contact[k]) != LonePair::None) {
      weights[kSrbStates * k + 2] *= config_.lone_pair_yaw_weight_share;
      weights[kSrbStates * k + 8] *= config_.lone_pair_yaw_weight_share;
    }
    weights[kSrbStates * k + 12] = 0.0;
  }
  Eigen::Matrix<double, kSrbStates * kMpcHorizon, 1> error;  // Aqp x0 - Xref
  error = a_qp_ * input.x0;
  for (int k = 0; k < kMpcHorizon; ++k) error.segment<kSrbStates>(kSrbStates * k) -= input.x_ref[k];

  problem_.resize({n, 0, kRowsPerFoot * n / 3});
  auto b_view = b_kept_.leftCols(n);
  auto weighted = weighted_b_.leftCols(n);
  weighted.noalias() = weights.asDiagonal() * b_view;
  // H = 2 B' W B + 2 alpha I, block by block. The forces of step k move only the states from
  // step k on (block (i, k) of B is zero for i < k), so block (j, k), j >= k, of H sums over the
  // states from step j on: a quarter of the dense product's work. The upper triangle mirrors it
  std::array<int, kMpcHorizon + 1> step_start{};  // kept variables of step k: [step_start[k], step_start[k + 1])
  for (int k = 0, v = 0; k <= kMpcHorizon; ++k) {
    step_start[static_cast<std::size_t>(k)] = v;
    while (v < n && kept_[static_cast<std::size_t>(v)] / kInputs == k) ++v;
  }
  constexpr int kPredictedRows = kSrbStates * kMpcHorizon;
  for (int j = 0; j < kMpcHorizon; ++j) {
    const int first_j = step_start[static_cast<std::size_t>(j)];
    const int count_j = step_start[static_cast<std::size_t>(j) + 1] - first_j;
    if (count_j == 0) continue;
    const int first_row = kSrbStates * j;
    const int rows = kPredictedRows - first_row;
    for (int k = 0; k <= j; ++k) {
      const int first_k = step_start[static_cast<std::size_t>(k)];
      const int count_k = step_start[static_cast<std::size_t>(k) + 1] - first_k;
      if (count_k == 0) continue;
      problem_.hessian.block(first_j, first_k, count_j, count_k).noalias() =
          2.0 * b_view.block(first_row, first_j, rows, count_j).transpose() *
          weighted.block(first_row, first_k, rows, count_k);
    }
  }
  for (int j = 1; j < n; ++j) problem_.hessian.col(j).head(j) = problem_.hessian.row(j).head(j).transpose();
  problem_.hessian.diagonal().array() += 2.0 * config_.force_weight;
  problem_.linear.noalias() = 2.0 * weighted.transpose() * error;

  // friction pyramid and force limits, five rows per foot force
  const double mu = input.friction > 0.0 ? input.friction : config_.friction;
  const double inf = std::numeric_limits<double>::infinity();
  for (int f = 0; f < n / 3; ++f) {
    const int col = 3 * f;
    const int row = kRowsPerFoot * f;
    problem_.ineq_matrix(row, col + 2) = 1.0;  // 0 <= fz <= fmax
    problem_.ineq_lower[row] = 0.0;
    problem_.ineq_upper[row] = config_.force_max_n;
    for (int side = 0; side < 4; ++side) {
      const int r = row + 1 + side;
      if (input.pyramid == FrictionPyramid::Square) {  // +-fx <= mu fz, +-fy <= mu fz
        problem_.ineq_matrix(r, col + side / 2) = (side % 2 == 0) ? 1.0 : -1.0;
      } else {  // +-fx +-fy <= mu fz
        problem_.ineq_matrix(r, col) = (side % 2 == 0) ? 1.0 : -1.0;
        problem_.ineq_matrix(r, col + 1) = (side / 2 == 0) ? 1.0 : -1.0;
      }
      problem_.ineq_matrix(r, col + 2) = -mu;
      problem_.ineq_lower[r] = -inf;
      problem_.ineq_upper[r] = 0.0;
    }
  }
}

MpcOutput ConvexMpc::solve(const MpcInput& input) {
  MpcOutput output;
  for (auto& force : output.forces) force.setZero();
  if (!input_is_finite(input)) return output;
  build(input);
  output.variables = kept_count_;
  if (kept_count_ == 0) {
    // no foot on the ground over the whole horizon: nothing to push with
    output.status = qp::QpStatus::Solved;
    return output;
  }
  output.status = solver_->solve(problem_, solution_);
  if (output.status != qp::QpStatus::Solved || !solution_.x.allFinite()) {
    if (output.status == qp::QpStatus::Solved) output.status = qp::QpStatus::InvalidInput;
    return output;
  }
  // the first horizon step's kept variables come first
  for (int v = 0; v < kept_count_ && kept_[v] < kInputs; ++v) {
    output.forces[static_cast<std::size_t>(kept_[v] / 3)][kept_[v] % 3] = solution_.x[v];
  }
  return output;
}

}  // namespace cerebellum
