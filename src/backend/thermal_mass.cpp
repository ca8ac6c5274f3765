#include "backend/thermal_mass.hpp"

#include <cmath>

namespace cerebellum {

ThermalMass::ThermalMass(const ThermalMassParameters& parameters)
    : parameters_(parameters), temperature_c_(parameters.ambient_c) {}

void ThermalMass::update(double heating_w, double dt_s) {
  const double steady_c = parameters_.ambient_c + heating_w * parameters_.thermal_resistance_k_per_w;
  const double time_constant_s = parameters_.thermal_resistance_k_per_w * parameters_.heat_capacity_j_per_k;
  temperature_c_ += (steady_c - temperature_c_) * (1.0 - std::exp(-dt_s / time_constant_s));
}

}  // namespace cerebellum
