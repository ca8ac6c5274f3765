// One lumped body that a heat flow warms and conduction to the ambient cools: the thermal model
// shared by the simulated robot's parts that report a temperature (the main board's IMU).
#pragma once

namespace cerebellum {

struct ThermalMassParameters {
  double ambient_c = 25.0;
  double thermal_resistance_k_per_w = 1.0;  // to the ambient
  double heat_capacity_j_per_k = 100.0;
};

class ThermalMass {
 public:
  explicit ThermalMass(const ThermalMassParameters& parameters);
  // heating_w flows in for dt_s: the exact step of the first-order law towards its steady state
  // (ambient + heating R), so a long step neither overshoots nor depends on the loop's period
  void update(double heating_w, double dt_s);
  double temperature_c() const { return temperature_c_; }

 private:
  ThermalMassParameters parameters_;
  double temperature_c_;
};

}  // namespace cerebellum
