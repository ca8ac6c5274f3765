#include "estimation/linear_kalman_filter.hpp"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>

namespace cerebellum {
namespace {

constexpr int kFootOffset = 6;
constexpr int kRowsPerLeg = LinearKalmanFilter::kMeasurementsPerLeg;
using LegMatrix = Eigen::Matrix<double, kRowsPerLeg, LinearKalmanFilter::kStateSize>;

int foot_index(std::size_t leg) { return kFootOffset + 3 * static_cast<int>(leg); }

bool leg_is_finite(const LegObservation& leg) {
  return leg.foot_relative_world.allFinite() && leg.body_velocity_world.allFinite() && std::isfinite(leg.trust) &&
         std::isfinite(leg.ground_height_m);
}

bool trust_is_finite(const LinearKalmanFilter::Trust& trust) {
  return std::all_of(trust.begin(), trust.end(), [](double t) { return std::isfinite(t); });
}

}  // namespace

LinearKalmanFilter::LinearKalmanFilter(const LinearKalmanFilterConfig& config) : config_(config) {}

void LinearKalmanFilter::reset() {
  x_.setZero();
  p_.setZero();
  initialized_ = false;
  valid_ = false;
  time_since_correction_s_ = 0.0;
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
  time_since_correction_s_ = 0.0;
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
  time_since_correction_s_ += dt;
  valid_ = true;
  return true;
}

bool LinearKalmanFilter::correct(const LegObservations& legs) {
  if (!initialized_ || !std::all_of(legs.begin(), legs.end(), leg_is_finite)) {
    valid_ = false;
    return false;
  }
  const double rel_var = config_.foot_relative_sigma_m * config_.foot_relative_sigma_m;
  const double vel_var = config_.foot_velocity_sigma_m_s * config_.foot_velocity_sigma_m_s;
  const double height_var = config_.foot_height_sigma_m * config_.foot_height_sigma_m;
  // the legs' noises are independent, so one leg after another gives the batch update exactly
  StateVector x = x_;
  Covariance p = p_;
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
    const int f = foot_index(leg);
    // H P and S = H P H^T + R, with H's rows: foot - trunk position, trunk velocity, foot height
    LegMatrix hp;
    hp.topRows<3>() = p.middleRows<3>(f) - p.topRows<3>();
    hp.middleRows<3>(3) = p.middleRows<3>(3);
    hp.row(6) = p.row(f + 2);
    Eigen::Matrix<double, kRowsPerLeg, kRowsPerLeg> s;
    s.leftCols<3>() = hp.middleCols<3>(f) - hp.leftCols<3>();
    s.middleCols<3>(3) = hp.middleCols<3>(3);
    s.col(6) = hp.col(f + 2);
    // information in proportion to trust
    const double inverse_trust = 1.0 / std::max(std::clamp(legs[leg].trust, 0.0, 1.0), config_.min_trust);
    s.diagonal().head<3>().array() += rel_var * inverse_trust;
    s.diagonal().segment<3>(3).array() += vel_var * inverse_trust;
    s(6, 6) += height_var * inverse_trust;

    Eigen::Matrix<double, kRowsPerLeg, 1> innovation;
    innovation.head<3>() = legs[leg].foot_relative_world - (x.segment<3>(f) - x.head<3>());
    innovation.segment<3>(3) = legs[leg].body_velocity_world - x.segment<3>(3);
    innovation(6) = legs[leg].ground_height_m - x(f + 2);
    // a velocity far outside what the filter expects is a slipping or not yet planted foot:
    // that leg's velocity then counts as if the foot were untrusted
    const Eigen::Vector3d velocity_innovation = innovation.segment<3>(3);
    const double distance_sq = velocity_innovation.dot(s.block<3, 3>(3, 3).ldlt().solve(velocity_innovation));
    if (distance_sq > config_.velocity_gate_chi2) {
      ++gated_velocity_measurements_;
      s.diagonal().segment<3>(3).array() += vel_var / config_.min_trust;
    }

    // K = P H^T S^-1, kept as K^T = S^-1 (H P) since S and P are symmetric
    const Eigen::LDLT<Eigen::Matrix<double, kRowsPerLeg, kRowsPerLeg>> s_factor(s);
    if (s_factor.info() != Eigen::Success || !s_factor.isPositive()) {
      valid_ = false;
      return false;
    }
    const LegMatrix k_transpose = s_factor.solve(hp);
    x.noalias() += k_transpose.transpose() * innovation;
    p.noalias() -= k_transpose.transpose() * hp;
  }
  // the IMU carries the fast changes of velocity; the legs only correct its slow errors
  const Eigen::Vector3d velocity_change = x.segment<3>(3) - x_.segment<3>(3);
  const double max_change = config_.max_leg_velocity_correction_m_s2 * time_since_correction_s_;
  if (velocity_change.norm() > max_change) {
    const Eigen::Vector3d kept = velocity_change * (max_change / velocity_change.norm());
    x.segment<3>(3) = x_.segment<3>(3) + kept;
    // the part left out stays uncertain: without it the filter would refuse the same legs next
    // tick as if it had already moved, and a true correction (after a flight) would be locked out
    const Eigen::Vector3d left_out = velocity_change - kept;
    p.block<3, 3>(3, 3) += left_out * left_out.transpose();
    ++limited_velocity_corrections_;
  }
  p = 0.5 * (p + p.transpose()).eval();
  if (!x.allFinite() || !p.allFinite() || (p.diagonal().array() <= 0.0).any()) {
    valid_ = false;
    return false;
  }
  x_ = x;
  p_ = p;
  time_since_correction_s_ = 0.0;
  valid_ = true;
  return true;
}

}  // namespace cerebellum
