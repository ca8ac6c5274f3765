// The fault injector around a scripted robot: what each fault does to the readings and to the
// commands the motors get, when scenario faults start and end, and that no fault means no change.
#include "backend/fault_injecting_backend.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "backend/fake_backend.hpp"

namespace cerebellum {
namespace {

FaultRequest fault(const std::string& text) { return parse_fault(text).request.value(); }

struct Injected {
  explicit Injected(std::vector<TimedFault> scenario = {}) {
    auto inner = std::make_unique<FakeBackend>();
    fake = inner.get();
    fake->frame().imu_quat = {1.0, 0.0, 0.0, 0.0};
    fake->frame().imu_gyro = {0.1, 0.2, 0.3};
    fake->frame().battery = {true, 25.0, 2.0, 80.0};
    for (std::size_t i = 0; i < kNumJoints; ++i) fake->frame().q[i] = 0.1 * static_cast<double>(i);
    backend = std::make_unique<FaultInjectingBackend>(std::move(inner), nullptr, std::move(scenario));
  }
  SensorFrame step(const JointCommand& command = stiff()) {
    const SensorFrame frame = backend->read();
    backend->write(command);
    backend->advance(0.002);
    return frame;
  }
  static JointCommand stiff() {
    JointCommand command;
    command.kp.fill(50.0);
    command.kd.fill(1.0);
    command.tau_ff.fill(2.0);
    return command;
  }
  FakeBackend* fake = nullptr;
  std::unique_ptr<FaultInjectingBackend> backend;
};

TEST(FaultInjectingBackend, WithoutFaultsEverythingPassesThrough) {
  Injected robot;
  const SensorFrame before = robot.fake->frame();
  const SensorFrame frame = robot.step();
  EXPECT_EQ(frame.q, before.q);
  EXPECT_EQ(frame.imu_gyro[1], 0.2);
  EXPECT_EQ(frame.battery.state_of_charge_percent, 80.0);
  EXPECT_EQ(robot.fake->written().back().kp, Injected::stiff().kp);
}

TEST(FaultInjectingBackend, ADisconnectedMotorReportsItRepeatsItsLastReadingAndGetsNoTorque) {
  Injected robot;
  robot.step();
  ASSERT_EQ(robot.backend->request(fault("motor 4 disconnected")), "");
  const double last_q = robot.step().q[4];  // the request is taken at this read
  const SensorFrame frame = robot.step();
  EXPECT_EQ(frame.motor_faults[4], kMotorDisconnected);
  EXPECT_EQ(frame.motor_faults[3], kMotorOk);
  EXPECT_EQ(frame.q[4], last_q);
  const JointCommand& written = robot.fake->written().back();
  EXPECT_EQ(written.kp[4], 0.0);
  EXPECT_EQ(written.kd[4], 0.0);
  EXPECT_EQ(written.tau_ff[4], 0.0);
  EXPECT_EQ(written.kp[3], 50.0);
}

TEST(FaultInjectingBackend, ADeratedMotorGetsAFractionOfItsCommandAndAStuckOneHoldsItsAngle) {
  Injected robot;
  robot.step();
  robot.backend->request(fault("motor 1 derated 0.25"));
  robot.backend->request(fault("motor 2 stuck"));
  const SensorFrame frame = robot.step();
  const JointCommand& written = robot.fake->written().back();
  EXPECT_EQ(written.kp[1], 12.5);
  EXPECT_EQ(written.tau_ff[1], 0.5);
  EXPECT_EQ(written.q_des[2], 0.2);  // its angle when it seized
  EXPECT_EQ(written.kp[2], 200.0);
  // neither reports anything: the MC must notice by itself, or not
  EXPECT_EQ(frame.motor_faults[1], kMotorOk);
  EXPECT_EQ(frame.motor_faults[2], kMotorOk);
}

TEST(FaultInjectingBackend, ImuFaultsBiasFreezeDropAndPoisonTheSamples) {
  Injected robot;
  robot.step();
  robot.backend->request(fault("imu bias 0.05"));
  EXPECT_NEAR(robot.step().imu_gyro[0], 0.15, 1e-12);
  robot.backend->request(fault("imu stuck"));
  robot.step();
  robot.fake->frame().imu_gyro = {9.0, 9.0, 9.0};
  EXPECT_EQ(robot.step().imu_gyro[0], 0.1);
  robot.backend->request(fault("imu dropout"));
  EXPECT_EQ(robot.step().imu_quat[0], 0.0);
  robot.backend->request(fault("imu nan"));
  EXPECT_TRUE(std::isnan(robot.step().imu_accel[2]));
  robot.backend->request(fault("clear imu"));
  EXPECT_EQ(robot.step().imu_gyro[0], 9.0);
}

TEST(FaultInjectingBackend, AnOverCurrentReportsItsPhaseAndAnOverloadItsBitAndTheDriverStopsItsMotor) {
  Injected robot;
  robot.step();
  robot.backend->request(fault("motor 2 over_current C"));
  robot.backend->request(fault("motor 7 overload 8"));
  robot.backend->request(fault("motor 9 over_current"));
  const SensorFrame frame = robot.step();
  EXPECT_EQ(frame.motor_faults[2], kMotorOverCurrentPhaseC);
  EXPECT_EQ(frame.motor_faults[7], motor_overload(8));
  EXPECT_EQ(frame.motor_faults[9], kMotorOverCurrentPhaseA);  // phase A when not named
  const JointCommand& written = robot.fake->written().back();
  for (std::size_t i : {2u, 7u, 9u}) EXPECT_EQ(written.kp[i], 0.0) << "motor " << i;
  EXPECT_EQ(written.kp[3], 50.0);
}

TEST(FaultInjectingBackend, TheBatteryReportsTheInjectedChargeAndDrainsFromThere) {
  Injected robot;
  robot.step();
  robot.backend->request(fault("battery soc 15"));
  robot.backend->request(fault("battery drain 100"));
  double soc = robot.step().battery.state_of_charge_percent;
  EXPECT_NEAR(soc, 15.0, 1e-9);
  // 2 A for 1 s, 100 times faster, from 4.5 Ah: 1.235 % less
  for (int i = 0; i < 500; ++i) soc = robot.step().battery.state_of_charge_percent;
  EXPECT_NEAR(soc, 15.0 - 100.0 * 100.0 * 2.0 * 1.0 / 3600.0 / 4.5, 0.01);
  // a sag below the drivers' limit shows as their under-voltage
  robot.backend->request(fault("battery sag 10"));
  const SensorFrame sagged = robot.step();
  EXPECT_LT(sagged.battery.voltage_v, 18.0);
  for (std::uint32_t bits : sagged.motor_faults) EXPECT_EQ(bits, kMotorUnderVoltage);
  robot.backend->request(fault("clear battery"));
  EXPECT_EQ(robot.step().battery.state_of_charge_percent, 80.0);
}

TEST(FaultInjectingBackend, ScenarioFaultsStartAtTheirTimeAndEndAfterTheirDuration) {
  Injected robot({{0.1, fault("motor 0 overload for 0.05")}, {0.02, fault("motor 11 driver_fault")}});
  double overload_from = -1, overload_to = -1, driver_from = -1;
  SensorFrame frame;
  for (int i = 0; i < 100; ++i) {
    frame = robot.step();
    if (frame.motor_faults[0] && overload_from < 0) overload_from = frame.time_s;
    if (!frame.motor_faults[0] && overload_from >= 0 && overload_to < 0) overload_to = frame.time_s;
    if (frame.motor_faults[11] && driver_from < 0) driver_from = frame.time_s;
  }
  EXPECT_NEAR(driver_from, 0.02, 1e-9);
  EXPECT_NEAR(overload_from, 0.1, 1e-9);
  EXPECT_NEAR(overload_to, 0.15, 1e-9);
  EXPECT_EQ(frame.motor_faults[11], kMotorDriverFault);  // no duration: still on
}

TEST(FaultInjectingBackend, FootFaultsNeedASimulationAndTheMailboxIsBounded) {
  Injected robot;
  EXPECT_NE(robot.backend->request(fault("foot 0 slippery")).find("need a simulated robot"), std::string::npos);
  std::string last;
  for (int i = 0; i < 100 && last.empty(); ++i) last = robot.backend->request(fault("imu stuck"));
  EXPECT_NE(last.find("too many fault requests"), std::string::npos);
}

}  // namespace
}  // namespace cerebellum
