// Linear Kalman filter for the trunk's position and velocity and the four foot points, all in the
// world frame. The IMU's world acceleration drives the prediction; leg kinematics of the feet on
// the ground correct it. Fixed-size matrices: nothing is allocated after construction.
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstdint>

#include "core/joint_layout.hpp"

namespace cerebellum {

// noise figures, each a standard deviation (or a density for the random walks)
struct LinearKalmanFilterConfig {
  // white acceleration the IMU term misses: sensor noise, IMU lever arm, tilt error ((m/s^2)/sqrt(Hz))
  double accel_noise_density = 0.5;
  // random walk of a foot point: slip of a planted foot, free motion of a foot in the air (m/sqrt(s))
  double stance_foot_drift = 0.002;
  double swing_foot_drift = 1.0;
  // a trusted foot's measurements: leg kinematics error (m), foot not quite still (m/s), ground
  // unevenness (m)
  double foot_relative_sigma_m = 0.005;
  double foot_velocity_sigma_m_s = 0.05;
  double foot_height_sigma_m = 0.005;
  // a leg's measurement variances are divided by max(trust, min_trust): trust 0 -> x 1/min_trust
  double min_trust = 1e-4;
  // a leg's velocity whose normalised squared innovation exceeds this (chi-square, 3 degrees of
  // freedom; 16.3 = 99.9 %) is treated as from an untrusted foot
  double velocity_gate_chi2 = 16.3;
  // the legs may change the trunk velocity by at most this much per second of prediction beyond
  // what the IMU integrated (m/s^2). An IMU's own errors (bias, the gravity a tilt error leaks in)
  // stay below 0.5 m/s^2; legs that pull faster are feet in the air or sliding while the plan says
  // stance: a flying trot's stance pair that bounced off the ground pulled the estimate 1.3 m/s
  // off in 40 ms, and a fall followed. Infinity: the plain Kalman update
  double max_leg_velocity_correction_m_s2 = 5.0;
  // uncertainty right after initialize()
  double initial_position_sigma_m = 0.02;
  double initial_velocity_sigma_m_s = 0.1;
  double initial_foot_sigma_m = 0.02;
};

// what one leg's kinematics say, all in world axes
struct LegObservation {
  Eigen::Vector3d foot_relative_world = Eigen::Vector3d::Zero();  // foot point minus trunk origin
  Eigen::Vector3d body_velocity_world = Eigen::Vector3d::Zero();  // trunk velocity if this foot is still
  double trust = 0.0;                                             // 0..1: how surely the foot is planted
  double ground_height_m = 0.0;  // world z of the ground under the foot (0: flat ground at the origin)
};
using LegObservations = std::array<LegObservation, kNumLegs>;

class LinearKalmanFilter {
 public:
  static constexpr int kStateSize = 6 + 3 * static_cast<int>(kNumLegs);  // p, v, feet
  static constexpr int kMeasurementsPerLeg = 7;  // foot relative position 3, trunk velocity 3, foot height 1
  using StateVector = Eigen::Matrix<double, kStateSize, 1>;
  using Covariance = Eigen::Matrix<double, kStateSize, kStateSize>;
  using Trust = std::array<double, kNumLegs>;

  explicit LinearKalmanFilter(const LinearKalmanFilterConfig& config = {});

  // forget everything: not initialised, not valid
  void reset();
  // start from a known state with the configured initial uncertainty
  void initialize(const Eigen::Vector3d& position, const Eigen::Vector3d& velocity,
                  const std::array<Eigen::Vector3d, kNumLegs>& feet);

  // propagate by dt_s under the world acceleration (gravity removed); trust sets each foot's drift.
  // Non-finite or negative input, or no initialisation: skipped, returns false, valid() false.
  bool predict(const Eigen::Vector3d& accel_world, double dt_s, const Trust& trust);
  // fold in the legs' kinematics; the same skipping rules as predict(). The velocity moves at most
  // max_leg_velocity_correction_m_s2 times the time predicted since the last correction
  bool correct(const LegObservations& legs);

  bool initialized() const { return initialized_; }
  // false before initialize() and after a skipped step, until the next accepted step
  bool valid() const { return valid_; }
  // leg velocity measurements the innovation gate has set aside so far
  std::uint64_t gated_velocity_measurements() const { return gated_velocity_measurements_; }
  // corrections whose velocity change was cut to max_leg_velocity_correction_m_s2
  std::uint64_t limited_velocity_corrections() const { return limited_velocity_corrections_; }

  Eigen::Vector3d position() const { return x_.segment<3>(0); }
  Eigen::Vector3d velocity() const { return x_.segment<3>(3); }
  Eigen::Vector3d foot_position(std::size_t leg) const { return x_.segment<3>(6 + 3 * leg); }
  const StateVector& state() const { return x_; }
  const Covariance& covariance() const { return p_; }
  const LinearKalmanFilterConfig& config() const { return config_; }

 private:
  LinearKalmanFilterConfig config_;
  StateVector x_ = StateVector::Zero();
  Covariance p_ = Covariance::Zero();
  bool initialized_ = false;
  bool valid_ = false;
  std::uint64_t gated_velocity_measurements_ = 0;
  std::uint64_t limited_velocity_corrections_ = 0;
  double time_since_correction_s_ = 0.0;
};

}  // namespace cerebellum
