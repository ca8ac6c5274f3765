// The health protection: motor faults, battery, frozen IMU and untrusted state -> damping, then
// the motors off after 3 s; cleared when the cause is.
#include "safety/health_monitor.hpp"

#include <gtest/gtest.h>

namespace cerebellum {
namespace {

constexpr double kTickS = 0.002;

// a valid state whose IMU sample and joints change every tick, like a live robot's
RobotState live_state(int tick) {
  RobotState state;
  state.valid = true;
  state.time_s = tick * kTickS;
  state.omega_body.x() = 1e-4 * (tick % 7);
  state.specific_force_body.z() += 1e-3 * (tick % 5);
  state.q.fill(0.01 * tick);
  return state;
}

// runs the monitor from tick `from` to `to` (exclusive) on states made by make; the last verdict
template <typename MakeState>
HealthVerdict run(HealthMonitor& monitor, int from, int to, MakeState make) {
  HealthVerdict verdict;
  for (int tick = from; tick < to; ++tick) verdict = monitor.update(make(tick));
  return verdict;
}

TEST(HealthMonitor, AHealthyRobotIsNotProtected) {
  HealthMonitor monitor;
  const HealthVerdict verdict = run(monitor, 0, 5000, live_state);
  EXPECT_EQ(verdict.protection, Protection::None);
  EXPECT_EQ(verdict.causes, kHealthOk);
}

TEST(HealthMonitor, AMotorErrorDampsAtOnceAndStopsTheMotorsAfterThreeSeconds) {
  HealthMonitor monitor;
  run(monitor, 0, 100, live_state);
  const auto faulty = [](int tick) {
    RobotState state = live_state(tick);
    state.motor_faults[5] = kMotorDisconnected;
    return state;
  };
  HealthVerdict verdict = monitor.update(faulty(100));
  EXPECT_EQ(verdict.protection, Protection::Damping);
  EXPECT_EQ(verdict.causes, kHealthMotorError);
  EXPECT_EQ(verdict.faulty_motors, 1u << 5);
  // 3 s = 1500 ticks after the first faulty one
  verdict = run(monitor, 101, 1599, faulty);
  EXPECT_EQ(verdict.protection, Protection::Damping);
  EXPECT_NEAR(verdict.protected_s, 2.996, 1e-9);
  verdict = run(monitor, 1599, 1601, faulty);
  EXPECT_EQ(verdict.protection, Protection::Stopped);
  // the error clears by itself: so does the protection, 0.5 s later
  verdict = run(monitor, 1601, 1850, live_state);
  EXPECT_EQ(verdict.protection, Protection::Stopped);
  verdict = monitor.update(live_state(1851));
  EXPECT_EQ(verdict.protection, Protection::None);
  // a new fault starts a new 3 s
  verdict = monitor.update(faulty(1852));
  EXPECT_EQ(verdict.protection, Protection::Damping);
  EXPECT_NEAR(verdict.protected_s, 0.0, 1e-12);
}

TEST(HealthMonitor, ATemperatureWarningProtectsLikeAnError) {
  HealthMonitor monitor;
  RobotState state = live_state(0);
  state.motor_faults[0] = kMotorTemperatureWarning;
  const HealthVerdict verdict = monitor.update(state);
  EXPECT_EQ(verdict.protection, Protection::Damping);
  EXPECT_EQ(verdict.causes, kHealthMotorWarning);
}

TEST(HealthMonitor, ABatteryAtItsCriticalLevelProtectsAndOneAboveDoesNot) {
  HealthMonitor monitor;
  RobotState state = live_state(0);
  state.battery.present = true;
  state.battery.voltage_v = 19.0;
  state.battery.state_of_charge_percent = 5.1;
  EXPECT_EQ(monitor.update(state).protection, Protection::None);
  state = live_state(1);
  state.battery = {true, 19.0, 2.0, 5.0};
  EXPECT_EQ(monitor.update(state).causes, kHealthBatteryCritical);
  state = live_state(2);
  state.battery = {true, std::nan(""), 2.0, 50.0};
  EXPECT_EQ(monitor.update(state).causes, kHealthBatteryReading);
  // no battery reading at all (a robot without one): nothing to protect from
  HealthMonitor without_battery;
  state = live_state(3);
  state.battery = {false, 0.0, 0.0, 0.0};
  EXPECT_EQ(without_battery.update(state).protection, Protection::None);
}

TEST(HealthMonitor, AStateInvalidForAGlitchIsLeftToTheGuardButLongerProtects) {
  HealthMonitor monitor;
  run(monitor, 0, 10, live_state);
  const auto invalid = [](int tick) {
    RobotState state = live_state(tick);
    state.valid = false;
    return state;
  };
  // 20 ms = 10 ticks; the first 10 invalid ticks span 18 ms
  EXPECT_EQ(run(monitor, 10, 20, invalid).protection, Protection::None);
  EXPECT_EQ(monitor.update(invalid(20)).causes, kHealthStateInvalid);
  EXPECT_EQ(run(monitor, 21, 271, live_state).protection, Protection::Damping);
  EXPECT_EQ(monitor.update(live_state(271)).protection, Protection::None);
}

TEST(HealthMonitor, ACauseThatComesAndGoesKeepsOneProtectionAndItsThreeSeconds) {
  // a sagging pack: the drivers trip, the load falls, the voltage recovers, they trip again
  HealthMonitor monitor;
  const auto flickering = [](int tick) {
    RobotState state = live_state(tick);
    if (tick % 100 < 10) state.motor_faults[0] = kMotorUnderVoltage;
    return state;
  };
  HealthVerdict verdict = run(monitor, 0, 1501, flickering);
  EXPECT_EQ(verdict.protection, Protection::Stopped);
  EXPECT_NEAR(verdict.protected_s, 3.0, 1e-9);
  EXPECT_EQ(verdict.causes, kHealthMotorError);
}

TEST(HealthMonitor, AFrozenImuOnAMovingRobotIsStuckButAStillRobotIsNot) {
  const auto frozen_imu = [](bool joints_move) {
    return [joints_move](int tick) {
      RobotState state = live_state(tick < 50 ? tick : 50);
      state.time_s = tick * kTickS;
      if (joints_move) state.q.fill(0.01 * tick);
      return state;
    };
  };
  HealthMonitor moving;
  // frozen from tick 50: 0.1 s later (tick 100) it is stuck
  EXPECT_EQ(run(moving, 0, 100, frozen_imu(true)).protection, Protection::None);
  EXPECT_EQ(moving.update(frozen_imu(true)(100)).causes, kHealthImuStuck);
  HealthMonitor still;
  EXPECT_EQ(run(still, 0, 1000, frozen_imu(false)).protection, Protection::None);
}

TEST(HealthMonitor, AStillRobotWhoseJointReadingsFlickerInTheirLastDigitsKeepsItsImu) {
  // a noiseless robot standing still: its IMU, sent as floats, repeats bit for bit while the
  // joints' readings flicker by a millionth of a radian (the stacked pair's A, a quiet real IMU)
  const auto flickering_joints = [](int tick) {
    RobotState state = live_state(0);
    state.time_s = tick * kTickS;
    state.q.fill(tick % 2 == 0 ? 1e-6 : -1e-6);
    return state;
  };
  HealthMonitor monitor;
  EXPECT_EQ(run(monitor, 0, 1000, flickering_joints).protection, Protection::None);
}

}  // namespace
}  // namespace cerebellum
