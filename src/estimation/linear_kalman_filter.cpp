#include "estimation/linear_kalman_filter.hpp"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>

namespace cerebellum {
namespace {

constexpr int kFootOffset = 6;
constexpr int kRowsPerLeg = 7;  // relative position 3, velocity 3, height 1

int foot_index(std::size_t leg) { return kFootOffset + 3 * static_cast<int>(leg); }

bool leg_is_finite(const LegObservation& leg) {
  return leg.foot_relative_world.allFinite() && leg.body_velocity_world.allFinite() && std::isfinite(leg.trust);
}

bool trust_is_finite(const LinearKalmanFilter::Trust& trust) {
  return std::all_of(trust.begin(), trust.end(), [](double t) { return std::isfinite(t); });
}

}  // namespace

LinearKalmanFilter::LinearKalmanFilter(const LinearKalmanFilterConfig& config) : config_(config) {
  const Eigen::Matrix3d identity = Eigen::Matrix3d::Identity();
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
    const int row = kRowsPerLeg * static_cast<int>(leg);
    // foot point minus trunk position
    h_.block<3, 3>(row, 0) = -identity;
    h_.block<3, 3>(row, foot_index(leg)) = identity;
    // trunk velocity
    h_.block<3, 3>(row + 3, 3) = identity;
    // foot height above the ground plane z = 0
    h_(row + 6, foot_index(leg) + 2) = 1.0;
  }
}

void LinearKalmanFilter::reset() {
  x_.setZero();
  p_.setZero();
  initialized_ = false;
  valid_ = false;
}

void LinearKalmanFilter::initialize(const Eigen::Vector3d& position, const Eigen::Vector3d& velocity,
                                    const std::array<Eigen::Vector3d, kNumLegs>& feet) {
  x_.segment<3>(0) = position;
  x_.segment<3>(3) = velocity;
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) x_.segment<3>(foot_index(leg)) = feet[leg];
  p_.setZero();
  p_.diagonal().segment<3>(0).setConstant(config_.initial_position_sigma_m * config_.initial_position_sigma_m);
  p_.diagonal().segment<3>(3).setConstant(config_.initial_velocity_sigma_m_s * config_.initial_velocity_sigma_m_s);
  p_.diagonal().tail<3 * kNumLegs>().setConstant(config_.initial_foot_sigma_m * config_.initial_foot_sigma_m);
  initialized_ = x_.allFinite() && p_.allFinite();
  valid_ = initialized_;
}

bool LinearKalmanFilter::predict(const Eigen::Vector3d& accel_world, double dt_s, const Trust& trust) {
  if (!initialized_ || !accel_world.allFinite() || !std::isfinite(dt_s) || dt_s < 0.0 || !trust_is_finite(trust)) {
    valid_ = false;
    return false;
  }
  const double dt = dt_s;
  // p += v dt + a dt^2 / 2, v += a dt; feet stay
  x_.segment<3>(0) += dt * x_.segment<3>(3) + 0.5 * dt * dt * accel_world;
  x_.segment<3>(3) += dt * accel_world;

  // P = A P A^T with A = [I dt I; 0 I] on the trunk block, identity on the feet, done block-wise
  p_.block<3, kStateSize>(0, 0) += dt * p_.block<3, kStateSize>(3, 0);
  p_.block<kStateSize, 3>(0, 0) += dt * p_.block<kStateSize, 3>(0, 3);

  // exact discretisation of white acceleration noise of density q: [dt^3/3, dt^2/2; dt^2/2, dt] q
  const double q = config_.accel_noise_density * config_.accel_noise_density;
  const double pp = q * dt * dt * dt / 3.0;
  const double pv = q * dt * dt / 2.0;
  const double vv = q * dt;
  for (int k = 0; k < 3; ++k) {
    p_(k, k) += pp;
    p_(k, k + 3) += pv;
    p_(k + 3, k) += pv;
    p_(k + 3, k + 3) += vv;
  }
  const double stance_drift = config_.stance_foot_drift * config_.stance_foot_drift;
  const double swing_drift = config_.swing_foot_drift * config_.swing_foot_drift;
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
    const double t = std::clamp(trust[leg], 0.0, 1.0);
    const double foot_variance_rate = t * stance_drift + (1.0 - t) * swing_drift;
    for (int k = 0; k < 3; ++k) p_(foot_index(leg) + k, foot_index(leg) + k) += foot_variance_rate * dt;
  }
  valid_ = true;
  return true;
}

bool LinearKalmanFilter::correct(const LegObservations& legs) {
  if (!initialized_ || !std::all_of(legs.begin(), legs.end(), leg_is_finite)) {
    valid_ = false;
    return false;
  }
  MeasurementVector z;
  MeasurementVector r_diagonal;
  const double rel_var = config_.foot_relative_sigma_m * config_.foot_relative_sigma_m;
  const double vel_var = config_.foot_velocity_sigma_m_s * config_.foot_velocity_sigma_m_s;
  const double height_var = config_.foot_height_sigma_m * config_.foot_height_sigma_m;
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
    const int row = kRowsPerLeg * static_cast<int>(leg);
    z.segment<3>(row) = legs[leg].foot_relative_world;
    z.segment<3>(row + 3) = legs[leg].body_velocity_world;
    z(row + 6) = 0.0;
    // information in proportion to trust
    const double inverse_trust = 1.0 / std::max(std::clamp(legs[leg].trust, 0.0, 1.0), config_.min_trust);
    r_diagonal.segment<3>(row).setConstant(rel_var * inverse_trust);
    r_diagonal.segment<3>(row + 3).setConstant(vel_var * inverse_trust);
    r_diagonal(row + 6) = height_var * inverse_trust;
  }

  // K = P H^T S^-1, computed as K^T = S^-1 (H P) since S and P are symmetric
  const MeasurementMatrix hp = h_ * p_;
  Eigen::Matrix<double, kMeasurementSize, kMeasurementSize> s = hp * h_.transpose();
  s.diagonal() += r_diagonal;
  const Eigen::LDLT<Eigen::Matrix<double, kMeasurementSize, kMeasurementSize>> s_factor(s);
  if (s_factor.info() != Eigen::Success || !s_factor.isPositive()) {
    valid_ = false;
    return false;
  }
  const GainMatrix k = s_factor.solve(hp).transpose();
  const StateVector x_new = x_ + k * (z - h_ * x_);

  // Joseph form keeps P symmetric positive definite: (I - K H) P (I - K H)^T + K R K^T
  const Covariance i_kh = Covariance::Identity() - k * h_;
  Covariance p_new = i_kh * p_ * i_kh.transpose() + k * r_diagonal.asDiagonal() * k.transpose();
  p_new = 0.5 * (p_new + p_new.transpose()).eval();
  if (!x_new.allFinite() || !p_new.allFinite()) {
    valid_ = false;
    return false;
  }
  x_ = x_new;
  p_ = p_new;
  valid_ = true;
  return true;
}

}  // namespace cerebellum
