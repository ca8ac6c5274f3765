// QPs shaped like the locomotion controllers': a condensed single-rigid-body MPC over stance-foot
// forces with friction pyramids, and the 12-variable balance QP. Used by tests and benchmarks.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include <Eigen/Dense>

#include "control/qp/qp_problem.hpp"
#include "core/robot_model.hpp"

namespace cerebellum::qp::fixtures {

using StanceSchedule = std::vector<std::array<bool, 4>>;  // per MPC step, legs FR, FL, RR, RL

struct ForceLimits {
  double mu = 0.4;
  double fz_max_n = 150.0;
};

inline constexpr int kMpcStates = 13;  // rpy, p, omega, v, gravity
inline constexpr double kGravity = 9.81;

// trot: diagonal pairs FR+RL and FL+RR alternate every half period (2 stance feet per step)
inline StanceSchedule trot_schedule(std::size_t horizon, std::size_t half_period_steps) {
  StanceSchedule s(horizon);
  for (std::size_t k = 0; k < horizon; ++k) {
    const bool first_pair = (k / half_period_steps) % 2 == 0;
    s[k] = {first_pair, !first_pair, !first_pair, first_pair};
  }
  return s;
}

inline StanceSchedule stand_schedule(std::size_t horizon) { return StanceSchedule(horizon, {true, true, true, true}); }

inline Eigen::Matrix3d cross_matrix(const Eigen::Vector3d& r) {
  Eigen::Matrix3d m;
  m << 0.0, -r.z(), r.y(), r.z(), 0.0, -r.x(), -r.y(), r.x(), 0.0;
  return m;
}

// feet under the hips of a body standing 0.25 m high, jittered by up to +-2 cm
inline std::array<Eigen::Vector3d, 4> jittered_feet(std::mt19937& rng) {
  std::uniform_real_distribution<double> jitter(-0.02, 0.02);
  const double y = robot::kHipY + robot::kAbadLength;
  const std::array<Eigen::Vector3d, 4> nominal{
      Eigen::Vector3d(robot::kHipX, -y, -0.25), Eigen::Vector3d(robot::kHipX, y, -0.25),
      Eigen::Vector3d(-robot::kHipX, -y, -0.25), Eigen::Vector3d(-robot::kHipX, y, -0.25)};
  std::array<Eigen::Vector3d, 4> feet;
  for (std::size_t i = 0; i < 4; ++i) {
    feet[i] = nominal[i] + Eigen::Vector3d(jitter(rng), jitter(rng), jitter(rng));
  }
  return feet;
}

// appends the 5 friction-pyramid rows of one foot whose force starts at variable `col`
inline void add_friction_rows(QpProblem& p, Eigen::Index& row, Eigen::Index col, const ForceLimits& limits) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  const double mu = limits.mu;
  // +-fx - mu fz <= 0, +-fy - mu fz <= 0, 0 <= fz <= fz_max
  const std::array<std::array<double, 3>, 4> faces{
      {{1.0, 0.0, -mu}, {-1.0, 0.0, -mu}, {0.0, 1.0, -mu}, {0.0, -1.0, -mu}}};
  for (const auto& face : faces) {
    p.ineq_matrix.block<1, 3>(row, col) = Eigen::RowVector3d(face.data());
    p.ineq_lower(row) = -inf;
    p.ineq_upper(row) = 0.0;
    ++row;
  }
  p.ineq_matrix(row, col + 2) = 1.0;
  p.ineq_lower(row) = 0.0;
  p.ineq_upper(row) = limits.fz_max_n;
  ++row;
}

// condensed MPC: states x_{k+1} = Ad x_k + Bd_k u_k (yaw-only single rigid body, 30 ms steps,
// first-order discretisation), cost sum |x_k - x_ref|_L^2 + alpha |u|^2 with the reference
// weights; only stance-foot forces are variables. The feet are randomised, and so is x0 when
// `disturbed`.
inline QpProblem make_condensed_mpc_qp(const StanceSchedule& stance, std::mt19937& rng, const ForceLimits& limits = {},
                                       bool disturbed = true) {
  using StateMatrix = Eigen::Matrix<double, kMpcStates, kMpcStates>;
  const std::size_t horizon = stance.size();
  const double dt_s = 0.03;
  const double alpha = 4e-5;
  const std::array<double, kMpcStates> weights{0.25, 0.25, 10, 2, 2, 50, 0, 0, 0.3, 0.2, 0.2, 0.1, 0};
  std::uniform_real_distribution<double> yaw_rad(-0.5, 0.5);
  const double yaw = yaw_rad(rng);
  const Eigen::Matrix3d rz = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  const Eigen::Vector3d inertia_body(robot::kMpcInertiaDiag.data());
  const Eigen::Matrix3d inertia_inv = (rz * inertia_body.asDiagonal() * rz.transpose()).inverse();

  StateMatrix a_cont = StateMatrix::Zero();
  a_cont.block<3, 3>(0, 6) = rz.transpose();
  a_cont.block<3, 3>(3, 9) = Eigen::Matrix3d::Identity();
  a_cont(11, 12) = -1.0;
  const StateMatrix a_disc = StateMatrix::Identity() + dt_s * a_cont;

  // column offsets of each step's stance-foot forces
  std::vector<Eigen::Index> step_offset(horizon + 1, 0);
  for (std::size_t k = 0; k < horizon; ++k) {
    const auto feet = std::count(stance[k].begin(), stance[k].end(), true);
    step_offset[k + 1] = step_offset[k] + 3 * feet;
  }
  const Eigen::Index n = step_offset.back();
  const auto state_row = [](std::size_t k) { return static_cast<Eigen::Index>(k) * kMpcStates; };
  const Eigen::Index states = state_row(horizon);

  // stacked prediction X = Aqp x0 + Bqp U
  Eigen::MatrixXd aqp(states, kMpcStates);
  Eigen::MatrixXd bqp = Eigen::MatrixXd::Zero(states, n);
  StateMatrix power = a_disc;
  for (std::size_t k = 0; k < horizon; ++k) {
    aqp.middleRows<kMpcStates>(state_row(k)) = power;
    power = a_disc * power;
  }
  for (std::size_t j = 0; j < horizon; ++j) {
    const auto feet = jittered_feet(rng);
    Eigen::MatrixXd b_step = Eigen::MatrixXd::Zero(kMpcStates, step_offset[j + 1] - step_offset[j]);
    Eigen::Index col = 0;
    for (std::size_t leg = 0; leg < 4; ++leg) {
      if (!stance[j][leg]) continue;
      b_step.block<3, 3>(6, col) = dt_s * inertia_inv * cross_matrix(feet[leg]);
      b_step.block<3, 3>(9, col) = (dt_s / robot::kMpcMassKg) * Eigen::Matrix3d::Identity();
      col += 3;
    }
    Eigen::MatrixXd propagated = b_step;
    for (std::size_t k = j; k < horizon; ++k) {
      bqp.block(state_row(k), step_offset[j], kMpcStates, b_step.cols()) = propagated;
      propagated = a_disc * propagated;
    }
  }

  // disturbed: a tilted, spinning body off its commanded velocity, asked to run forward at
  // 0.3-1.5 m/s at 0.27 m height with level orientation; otherwise at rest on its reference
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const double d = disturbed ? 1.0 : 0.0;
  Eigen::Matrix<double, kMpcStates, 1> x0 = Eigen::Matrix<double, kMpcStates, 1>::Zero();
  x0.head<2>() = d * 0.15 * Eigen::Vector2d(unit(rng), unit(rng));
  x0(2) = yaw;
  x0(5) = 0.27 + d * 0.03 * unit(rng);
  x0.segment<3>(6) = d * 1.5 * Eigen::Vector3d(unit(rng), unit(rng), unit(rng));
  x0.segment<3>(9) = d * Eigen::Vector3d(0.5 + 0.5 * unit(rng), 0.4 * unit(rng), 0.2 * unit(rng));
  x0(12) = kGravity;
  const double speed_mps = d * (0.9 + 0.6 * unit(rng));
  Eigen::VectorXd x_ref(states);
  for (std::size_t k = 0; k < horizon; ++k) {
    Eigen::Matrix<double, kMpcStates, 1> ref = Eigen::Matrix<double, kMpcStates, 1>::Zero();
    ref(2) = yaw;
    ref(3) = speed_mps * dt_s * static_cast<double>(k + 1);
    ref(5) = 0.27;
    ref(9) = speed_mps;
    ref(12) = kGravity;
    x_ref.segment<kMpcStates>(state_row(k)) = ref;
  }
  const Eigen::VectorXd l_diag =
      Eigen::Matrix<double, kMpcStates, 1>(weights.data()).replicate(static_cast<Eigen::Index>(horizon), 1);

  QpProblem p;
  p.resize({n, 0, 5 * n / 3});
  const Eigen::MatrixXd weighted_b = l_diag.asDiagonal() * bqp;
  p.hessian = 2.0 * (bqp.transpose() * weighted_b + alpha * Eigen::MatrixXd::Identity(n, n));
  p.linear = 2.0 * weighted_b.transpose() * (aqp * x0 - x_ref);
  Eigen::Index row = 0;
  for (Eigen::Index col = 0; col < n; col += 3) add_friction_rows(p, row, col, limits);
  return p;
}

// balance QP: four stance forces produce a desired body wrench (weight plus a random push
// correction); cost |A f - w|_S^2 + alpha |f|^2, friction pyramids on every foot
inline QpProblem make_balance_qp(std::mt19937& rng, const ForceLimits& limits = {}) {
  std::uniform_real_distribution<double> small(-1.0, 1.0);
  const auto feet = jittered_feet(rng);
  Eigen::Matrix<double, 6, 12> a;
  for (std::size_t leg = 0; leg < 4; ++leg) {
    const Eigen::Index col = 3 * static_cast<Eigen::Index>(leg);
    a.block<3, 3>(0, col) = Eigen::Matrix3d::Identity();
    a.block<3, 3>(3, col) = cross_matrix(feet[leg]);
  }
  Eigen::Matrix<double, 6, 1> wrench;
  wrench << 25.0 * small(rng), 25.0 * small(rng), robot::kMpcMassKg * kGravity + 20.0 * small(rng), 8.0 * small(rng),
      8.0 * small(rng), 4.0 * small(rng);
  Eigen::Matrix<double, 6, 1> s_diag;
  s_diag << 1.0, 1.0, 10.0, 20.0, 20.0, 10.0;
  const double alpha = 1e-3;

  QpProblem p;
  p.resize({12, 0, 20});
  p.hessian = 2.0 * (a.transpose() * s_diag.asDiagonal() * a + alpha * Eigen::Matrix<double, 12, 12>::Identity());
  p.linear = -2.0 * a.transpose() * s_diag.asDiagonal() * wrench;
  Eigen::Index row = 0;
  for (Eigen::Index col = 0; col < 12; col += 3) add_friction_rows(p, row, col, limits);
  return p;
}

}  // namespace cerebellum::qp::fixtures
