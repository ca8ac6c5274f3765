#include "backend/fault_injecting_backend.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "backend/battery_model.hpp"
#include "backend/motor_model.hpp"

namespace cerebellum {
namespace {

constexpr std::size_t kMailboxCapacity = 64;
// a seized joint: the motor holds the angle it had with its full stiffness
constexpr double kStuckKp = 200.0;
constexpr double kStuckKd = 10.0;
// the coil temperature an injected over-temperature reports (above the 87 deg C shutdown)
constexpr double kInjectedCoilTemperatureC = 90.0;

// the MotorFault bits a driver reports for an injected motor fault (the silent ones report none);
// value: the over-current's phase, the overload's bit (the request's value)
std::uint32_t reported_bits(FaultKind kind, double value) {
  switch (kind) {
    case FaultKind::Disconnected: return kMotorDisconnected;
    case FaultKind::OverTemperature: return kMotorOverTemperature | kMotorTemperatureWarning;
    case FaultKind::DriverFault: return kMotorDriverFault;
    case FaultKind::UnderVoltage: return kMotorUnderVoltage;
    case FaultKind::OverVoltage: return kMotorOverVoltage;
    case FaultKind::OverCurrent: return motor_over_current(static_cast<MotorPhase>(static_cast<int>(value)));
    case FaultKind::Overload: return motor_overload(static_cast<int>(value));
    case FaultKind::EncoderLost: return kMotorEncoderLost;
    default: return kMotorOk;
  }
}

double until(double now_s, double duration_s) { return duration_s > 0.0 ? now_s + duration_s : -1.0; }

bool expired(double until_s, double now_s) { return until_s >= 0.0 && now_s >= until_s - 1e-9; }

void copy_imu(const SensorFrame& from, SensorFrame& to) {
  to.imu_quat = from.imu_quat;
  to.imu_gyro = from.imu_gyro;
  to.imu_accel = from.imu_accel;
}

}  // namespace

FaultInjectingBackend::FaultInjectingBackend(std::unique_ptr<RobotBackend> inner, Simulation* simulation,
                                             std::vector<TimedFault> scenario)
    : inner_(std::move(inner)), simulation_(simulation), scenario_(std::move(scenario)) {
  std::stable_sort(scenario_.begin(), scenario_.end(),
                   [](const TimedFault& a, const TimedFault& b) { return a.at_s < b.at_s; });
  mailbox_.reserve(kMailboxCapacity);
  slippery_until_s_.fill(std::numeric_limits<double>::quiet_NaN());  // NaN: not slippery
}

std::string FaultInjectingBackend::request(const FaultRequest& request) {
  if (request.target == FaultTarget::Foot && request.kind != FaultKind::Clear && simulation_ == nullptr) {
    return "foot faults change the ground's friction and need a simulated robot";
  }
  std::lock_guard<std::mutex> lock(mailbox_mutex_);
  if (mailbox_.size() >= kMailboxCapacity) return "too many fault requests waiting for the next tick";
  mailbox_.push_back(request);
  return "";
}

void FaultInjectingBackend::take_requests(double now_s) {
  while (next_scenario_ < scenario_.size() && scenario_[next_scenario_].at_s <= now_s + 1e-9) {
    apply(scenario_[next_scenario_++].request, now_s);
  }
  // never wait for a requester: a busy mailbox is read at the next tick
  if (!mailbox_mutex_.try_lock()) return;
  for (const FaultRequest& request : mailbox_) apply(request, now_s);
  mailbox_.clear();
  mailbox_mutex_.unlock();
}

void FaultInjectingBackend::set_slippery(int leg, bool on, double friction) {
  const auto l = static_cast<std::size_t>(leg);
  if (simulation_ == nullptr) return;
  if (on) {
    simulation_->set_foot_friction(l, friction);
  } else if (!std::isnan(slippery_until_s_[l])) {
    simulation_->reset_foot_friction(l);
  }
  if (!on) slippery_until_s_[l] = std::numeric_limits<double>::quiet_NaN();
}

void FaultInjectingBackend::apply(const FaultRequest& request, double now_s) {
  const double until_s = until(now_s, request.duration_s);
  if (request.kind == FaultKind::Clear) {
    const bool all = request.target == FaultTarget::All;
    if (all || request.target == FaultTarget::Motor) {
      for (std::size_t i = 0; i < kNumJoints; ++i) {
        if (all || static_cast<int>(i) == request.index) motors_[i] = InjectedMotorFault{};
      }
    }
    if (all || request.target == FaultTarget::Imu) imu_ = ImuFault{};
    if (all || request.target == FaultTarget::Battery) {
      soc_ = drain_ = capacity_ = sag_ = BatteryFault{};
      reported_soc_valid_ = false;
    }
    if (all || request.target == FaultTarget::Foot) {
      for (int leg = 0; leg < static_cast<int>(kNumLegs); ++leg) {
        if (all || leg == request.index) set_slippery(leg, false, 0.0);
      }
    }
    return;
  }
  switch (request.target) {
    case FaultTarget::Motor: {
      const auto i = static_cast<std::size_t>(request.index);
      motors_[i] = InjectedMotorFault{request.kind, request.value, until_s, last_good_.q[i]};
      break;
    }
    case FaultTarget::Imu:
      imu_.kind = request.kind;
      imu_.value = request.value;
      imu_.until_s = until_s;
      copy_imu(last_good_, imu_.frozen);
      break;
    case FaultTarget::Battery: {
      BatteryFault& fault = request.kind == FaultKind::BatteryStateOfCharge ? soc_
                            : request.kind == FaultKind::BatteryDrain       ? drain_
                            : request.kind == FaultKind::BatteryCapacity    ? capacity_
                                                                            : sag_;
      fault = BatteryFault{true, request.value, until_s};
      if (request.kind == FaultKind::BatteryStateOfCharge) {
        // reported as given at this tick, drained from the next one on
        reported_soc_percent_ = request.value;
        reported_soc_valid_ = true;
        last_read_s_ = now_s;
      }
      break;
    }
    case FaultTarget::Foot:
      slippery_until_s_[static_cast<std::size_t>(request.index)] = until_s;
      set_slippery(request.index, true, request.value);
      break;
    case FaultTarget::All: break;
  }
}

void FaultInjectingBackend::expire(double now_s) {
  for (InjectedMotorFault& motor : motors_) {
    if (motor.kind != FaultKind::Clear && expired(motor.until_s, now_s)) motor = InjectedMotorFault{};
  }
  if (imu_.kind != FaultKind::Clear && expired(imu_.until_s, now_s)) imu_ = ImuFault{};
  for (BatteryFault* fault : {&soc_, &drain_, &capacity_, &sag_}) {
    if (fault->active && expired(fault->until_s, now_s)) *fault = BatteryFault{};
  }
  if (!soc_.active && !drain_.active && !capacity_.active) reported_soc_valid_ = false;
  for (int leg = 0; leg < static_cast<int>(kNumLegs); ++leg) {
    const double until_s = slippery_until_s_[static_cast<std::size_t>(leg)];
    if (!std::isnan(until_s) && expired(until_s, now_s)) set_slippery(leg, false, 0.0);
  }
}

void FaultInjectingBackend::apply_battery(SensorFrame& frame) {
  BatteryReading& battery = frame.battery;
  const bool charge_faulted = soc_.active || drain_.active || capacity_.active;
  if (!battery.present || (!charge_faulted && !sag_.active)) return;
  if (charge_faulted) {
    // the management system's own count: starts from the true charge (or the injected one) and
    // falls with the measured current, faster by the drain factor, against the injected capacity
    if (!reported_soc_valid_) {
      reported_soc_percent_ = battery.state_of_charge_percent;
      reported_soc_valid_ = true;
    }
    const double dt_s = std::max(0.0, frame.time_s - last_read_s_);
    const double capacity_ah = capacity_.active ? capacity_.value : robot::kBatteryCapacityAh;
    const double drain = drain_.active ? drain_.value : 1.0;
    reported_soc_percent_ =
        std::max(0.0, reported_soc_percent_ - drain * 100.0 * battery.current_a * dt_s / 3600.0 / capacity_ah);
    battery.state_of_charge_percent = reported_soc_percent_;
    battery.voltage_v = robot::kBatteryCells * cell_open_circuit_voltage_v(reported_soc_percent_) -
                        battery.current_a * robot::kBatteryInternalResistanceOhm;
  }
  if (sag_.active) battery.voltage_v -= sag_.value;
  // the drivers see the bus voltage the battery reports
  for (std::size_t i = 0; i < kNumJoints; ++i) {
    const std::uint32_t voltage_bits = kMotorUnderVoltage | kMotorOverVoltage;
    const std::uint32_t reported =
        motor_driver_faults(frame.temperature_c[i], battery.voltage_v, reported_faults_[i]) & voltage_bits;
    frame.motor_faults[i] = (frame.motor_faults[i] & ~voltage_bits) | reported;
  }
}

SensorFrame FaultInjectingBackend::read() {
  SensorFrame frame = inner_->read();
  const double now_s = frame.time_s;
  take_requests(now_s);
  expire(now_s);
  const SensorFrame truth = frame;
  // motors
  for (std::size_t i = 0; i < kNumJoints; ++i) {
    const InjectedMotorFault& motor = motors_[i];
    frame.motor_faults[i] |= reported_bits(motor.kind, motor.value);
    switch (motor.kind) {
      case FaultKind::Disconnected:
        // no answer: the last values it sent
        frame.q[i] = last_good_.q[i];
        frame.qd[i] = last_good_.qd[i];
        frame.tau[i] = 0.0;
        break;
      case FaultKind::EncoderLost:
        frame.q[i] = motor.q;
        frame.qd[i] = 0.0;
        break;
      case FaultKind::OverTemperature:
        frame.temperature_c[i] = std::max(frame.temperature_c[i], kInjectedCoilTemperatureC);
        break;
      case FaultKind::Hot: {
        // the driver warns and stops at the temperature it reads
        frame.temperature_c[i] = std::max(frame.temperature_c[i], motor.value);
        constexpr std::uint32_t kTemperatureBits = kMotorOverTemperature | kMotorTemperatureWarning;
        frame.motor_faults[i] |=
            motor_driver_faults(frame.temperature_c[i], frame.battery.voltage_v) & kTemperatureBits;
        break;
      }
      default: break;
    }
  }
  // IMU
  switch (imu_.kind) {
    case FaultKind::ImuBias:
      for (double& g : frame.imu_gyro) g += imu_.value;
      break;
    case FaultKind::ImuStuck: copy_imu(imu_.frozen, frame); break;
    case FaultKind::ImuDropout:
      frame.imu_quat = {0.0, 0.0, 0.0, 0.0};
      frame.imu_gyro = {};
      frame.imu_accel = {};
      break;
    case FaultKind::ImuNan: {
      const double nan = std::numeric_limits<double>::quiet_NaN();
      frame.imu_quat = {nan, nan, nan, nan};
      frame.imu_gyro = {nan, nan, nan};
      frame.imu_accel = {nan, nan, nan};
      break;
    }
    default: break;
  }
  // battery
  apply_battery(frame);
  reported_faults_ = frame.motor_faults;
  last_read_s_ = now_s;
  // a disconnected motor repeats what it last said
  last_good_ = truth;
  for (std::size_t i = 0; i < kNumJoints; ++i) {
    if (motors_[i].kind == FaultKind::Disconnected) {
      last_good_.q[i] = frame.q[i];
      last_good_.qd[i] = frame.qd[i];
    }
  }
  return frame;
}

void FaultInjectingBackend::write(const JointCommand& command) {
  JointCommand out = command;
  for (std::size_t i = 0; i < kNumJoints; ++i) {
    const InjectedMotorFault& motor = motors_[i];
    if (reported_faults_[i] & kMotorErrorBits) {
      // a driver in error has stopped its motor
      out.kp[i] = out.kd[i] = out.tau_ff[i] = out.qd_des[i] = 0.0;
    } else if (motor.kind == FaultKind::Stuck) {
      out.q_des[i] = motor.q;
      out.qd_des[i] = 0.0;
      out.kp[i] = kStuckKp;
      out.kd[i] = kStuckKd;
      out.tau_ff[i] = 0.0;
    } else if (motor.kind == FaultKind::Derated) {
      out.kp[i] *= motor.value;
      out.kd[i] *= motor.value;
      out.tau_ff[i] *= motor.value;
    }
  }
  inner_->write(out);
}

}  // namespace cerebellum
