// The robot's own health and the protection it calls for, whoever commands the robot: any motor
// error or warning, a battery at its critical level, an IMU that froze, or a state the estimator
// cannot trust for longer than a glitch -> high damping (the robot slowly lies down), and after
// 3 s of it the motors are switched off (emergency stop). Commands are ignored while it lasts;
// the causes clear by themselves when their conditions do (cyberdog2-highlevel.md section 5), and
// the protection ends once none has been seen for 0.5 s.
#pragma once

#include <array>
#include <cstdint>

#include "core/robot_state.hpp"

namespace cerebellum {

enum class Protection { None, Damping, Stopped };

// why the robot is protected, one bit per cause
enum HealthCause : std::uint32_t {
  kHealthOk = 0,
  kHealthMotorError = 1u << 0,
  kHealthMotorWarning = 1u << 1,
  kHealthBatteryCritical = 1u << 2,  // state of charge at or below the critical level
  kHealthBatteryReading = 1u << 3,   // the battery reports numbers that are not finite
  kHealthImuStuck = 1u << 4,         // IMU samples bit-identical while the joints move
  kHealthStateInvalid = 1u << 5,     // the estimator has not trusted its state for a while
};

struct HealthLimits {
  double stop_after_s = 3.0;              // damping, then the motors off
  double battery_critical_percent = 5.0;  // at or below: protection
  double imu_stuck_after_s = 0.1;         // identical IMU samples for this long
  double imu_stuck_joint_motion_rad = 0.01;  // ... while a joint turned this far: the robot moved
  double state_invalid_after_s = 0.02;    // shorter gaps are damped by the guard alone
  double clear_after_s = 0.5;             // a protection ends once every cause has been gone this long
};

struct HealthVerdict {
  Protection protection = Protection::None;
  std::uint32_t causes = kHealthOk;  // HealthCause bits of this tick
  std::uint32_t faulty_motors = 0;   // bit i: motor i reports an error or a warning
  double protected_s = 0.0;          // how long the protection has lasted (through short clear gaps)

  bool protecting() const { return protection != Protection::None; }
};

class HealthMonitor {
 public:
  explicit HealthMonitor(const HealthLimits& limits = {});
  // once per tick, with the estimator's state of this tick
  HealthVerdict update(const RobotState& state);

 private:
  bool imu_stuck(const RobotState& state);

  HealthLimits limits_;
  HealthVerdict verdict_;
  double protected_since_s_ = 0.0;
  double healthy_since_s_ = -1.0;  // while protecting: since when no cause has been seen (< 0: one is)
  double invalid_since_s_ = -1.0;
  // the last IMU-derived sample and joint angles, and since when the IMU has not changed
  bool have_sample_ = false;
  std::array<double, 10> imu_sample_{};
  JointArray<double> joints_{};
  double imu_still_since_s_ = 0.0;
  bool joints_moved_ = false;
};

}  // namespace cerebellum
