#include "safety/health_monitor.hpp"

#include <cmath>

namespace cerebellum {

HealthMonitor::HealthMonitor(const HealthLimits& limits) : limits_(limits) {}

bool HealthMonitor::imu_stuck(const RobotState& state) {
  // everything the estimator takes from the IMU; a live sensor never repeats it bit for bit
  const Eigen::Quaterniond& q = state.orientation;
  const Eigen::Vector3d& w = state.omega_body;
  const Eigen::Vector3d& f = state.specific_force_body;  // the accelerometer as it reads
  const std::array<double, 10> sample{q.w(), q.x(), q.y(), q.z(), w.x(), w.y(), w.z(), f.x(), f.y(), f.z()};
  if (!have_sample_ || sample != imu_sample_) {
    have_sample_ = true;
    imu_sample_ = sample;
    joints_ = state.q;
    imu_still_since_s_ = state.time_s;
    joints_moved_ = false;
    return false;
  }
  // a resting robot may hold its joints still too: only a frozen IMU on a moving robot is stuck.
  // Moving means a joint turned by a real angle: a still robot's readings flicker in their last
  // digits while a quiet IMU sent as floats repeats bit for bit (the stacked pair's noiseless A
  // protected B's standing robot so)
  for (std::size_t i = 0; i < kNumJoints; ++i) {
    if (std::abs(state.q[i] - joints_[i]) > limits_.imu_stuck_joint_motion_rad) joints_moved_ = true;
  }
  return joints_moved_ && state.time_s - imu_still_since_s_ >= limits_.imu_stuck_after_s - 1e-9;
}

HealthVerdict HealthMonitor::update(const RobotState& state) {
  std::uint32_t causes = kHealthOk;
  std::uint32_t faulty_motors = 0;
  for (std::size_t i = 0; i < kNumJoints; ++i) {
    const std::uint32_t faults = state.motor_faults[i];
    if (faults & kMotorErrorBits) causes |= kHealthMotorError;
    if (faults & kMotorWarningBits) causes |= kHealthMotorWarning;
    if (faults & (kMotorErrorBits | kMotorWarningBits)) faulty_motors |= 1u << i;
  }
  const BatteryReading& battery = state.battery;
  if (battery.present) {
    if (!std::isfinite(battery.state_of_charge_percent) || !std::isfinite(battery.voltage_v)) {
      causes |= kHealthBatteryReading;
    } else if (battery.state_of_charge_percent <= limits_.battery_critical_percent) {
      causes |= kHealthBatteryCritical;
    }
  }
  if (state.valid) {
    invalid_since_s_ = -1.0;
    if (imu_stuck(state)) causes |= kHealthImuStuck;
  } else {
    if (invalid_since_s_ < 0.0) invalid_since_s_ = state.time_s;
    if (state.time_s - invalid_since_s_ >= limits_.state_invalid_after_s - 1e-9) causes |= kHealthStateInvalid;
  }

  if (causes == kHealthOk) {
    if (!verdict_.protecting()) return verdict_;
    // a cause that comes and goes (a sagging pack, a flickering sensor) keeps one protection,
    // with its 3 s to the motors off, instead of starting a new one each time
    if (healthy_since_s_ < 0.0) healthy_since_s_ = state.time_s;
    if (state.time_s - healthy_since_s_ >= limits_.clear_after_s - 1e-9) {
      verdict_ = HealthVerdict{};
      healthy_since_s_ = -1.0;
      return verdict_;
    }
  } else {
    healthy_since_s_ = -1.0;
    if (!verdict_.protecting()) protected_since_s_ = state.time_s;
    verdict_.causes = causes;
    verdict_.faulty_motors = faulty_motors;
  }
  verdict_.protected_s = state.time_s - protected_since_s_;
  verdict_.protection = verdict_.protected_s >= limits_.stop_after_s - 1e-9 ? Protection::Stopped : Protection::Damping;
  return verdict_;
}

}  // namespace cerebellum
