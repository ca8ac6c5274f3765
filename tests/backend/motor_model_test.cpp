// The motor driver model against hand-computed values.
#include "backend/motor_model.hpp"

#include <gtest/gtest.h>

namespace cerebellum {
namespace {

TEST(MotorLaw, IsFeedForwardPlusPdOnPositionAndVelocity) {
  // 1.5 + 60 (0.5 - 0.2) + 2 (1 - 3) = 1.5 + 18 - 4
  EXPECT_DOUBLE_EQ(motor_law_torque(0.5, 1.0, 60.0, 2.0, 1.5, 0.2, 3.0), 15.5);
}

TEST(MotorLimit, ClampsToTwelveNewtonMetresAtLowSpeed) {
  const MotorLimits limits;
  EXPECT_DOUBLE_EQ(limit_motor_torque(15.5, 0.0, limits), 12.0);
  EXPECT_DOUBLE_EQ(limit_motor_torque(-40.0, 5.0, limits), -12.0);
  EXPECT_DOUBLE_EQ(limit_motor_torque(7.0, 11.0, limits), 7.0);
}

TEST(MotorLimit, DrivingTorqueFallsLinearlyAboveTheKneeSpeed) {
  const MotorLimits limits;  // full up to 11.52 rad/s, zero at 30.5 rad/s
  // at 21.01 rad/s: 12 * (30.5 - 21.01) / (30.5 - 11.52) = 12 * 9.49 / 18.98 = 6
  EXPECT_NEAR(limit_motor_torque(12.0, 21.01, limits), 6.0, 1e-12);
  EXPECT_NEAR(limit_motor_torque(-12.0, -21.01, limits), -6.0, 1e-12);
  EXPECT_DOUBLE_EQ(limit_motor_torque(12.0, 11.52, limits), 12.0);
  EXPECT_DOUBLE_EQ(limit_motor_torque(5.0, 30.5, limits), 0.0);
  EXPECT_DOUBLE_EQ(limit_motor_torque(5.0, 35.0, limits), 0.0);
}

TEST(MotorLimit, BrakingTorqueIsNotReducedBySpeed) {
  const MotorLimits limits;
  EXPECT_DOUBLE_EQ(limit_motor_torque(-12.0, 25.0, limits), -12.0);
  EXPECT_DOUBLE_EQ(limit_motor_torque(9.0, -28.0, limits), 9.0);
}

TEST(MotorThermal, HeatsTowardsTheSteadyStateOfCopperLoss) {
  MotorThermalParameters p;
  MotorThermalModel model(p);
  // 3.875 N m joint torque = 0.5 N m motor torque = 10 A; 100 A^2 * 0.173 ohm = 17.3 W
  for (int i = 0; i < 2000000; ++i) model.update(3.875, 0.001);
  const double steady = p.winding.ambient_c + 17.3 * p.winding.thermal_resistance_k_per_w;
  EXPECT_NEAR(model.temperature_c(), steady, 0.05);
  MotorThermalModel idle(p);
  idle.update(0.0, 10.0);
  EXPECT_DOUBLE_EQ(idle.temperature_c(), p.winding.ambient_c);
}

}  // namespace
}  // namespace cerebellum
