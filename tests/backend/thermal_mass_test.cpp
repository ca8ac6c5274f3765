#include "backend/thermal_mass.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace cerebellum {
namespace {

constexpr ThermalMassParameters kBoard{20.0, 0.5, 400.0};  // time constant 200 s, 10 W -> +5 K

// independent of the law's closed form: dT/dt = (P - (T - ambient) / R) / C, small explicit steps
double integrated_c(double heating_w, double seconds) {
  double t_c = kBoard.ambient_c;
  const double dt_s = 1e-3;
  for (double t = 0.0; t < seconds - 1e-12; t += dt_s) {
    t_c += (heating_w - (t_c - kBoard.ambient_c) / kBoard.thermal_resistance_k_per_w) * dt_s /
           kBoard.heat_capacity_j_per_k;
  }
  return t_c;
}

TEST(ThermalMass, StartsAtTheAmbientAndFollowsTheHeatBalanceIntegratedInSmallSteps) {
  ThermalMass mass(kBoard);
  EXPECT_DOUBLE_EQ(mass.temperature_c(), 20.0);
  for (int i = 0; i < 150; ++i) mass.update(10.0, 1.0);
  EXPECT_NEAR(mass.temperature_c(), integrated_c(10.0, 150.0), 1e-3);
}

TEST(ThermalMass, OneLongStepLandsWhereManyShortOnesDo) {
  ThermalMass one(kBoard), many(kBoard);
  one.update(10.0, 300.0);
  for (int i = 0; i < 150000; ++i) many.update(10.0, 0.002);
  EXPECT_NEAR(one.temperature_c(), many.temperature_c(), 1e-9);
  // and never past the steady state, however long the step
  ThermalMass huge(kBoard);
  huge.update(10.0, 1e6);
  EXPECT_NEAR(huge.temperature_c(), 25.0, 1e-9);
}

TEST(ThermalMass, WithoutHeatItCoolsBackTowardsTheAmbient) {
  ThermalMass mass(kBoard);
  mass.update(10.0, 1e6);
  mass.update(0.0, 200.0);  // one time constant: 1/e of the excess left
  EXPECT_NEAR(mass.temperature_c(), 20.0 + 5.0 * std::exp(-1.0), 1e-9);
}

}  // namespace
}  // namespace cerebellum
