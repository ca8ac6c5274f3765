// A scenario's model error: ranges, and one draw of them per run from the run's seed, so every run
// of a soak meets another robot and each run can be replayed alone (docs/sweeps.md).
#pragma once

#include <string>

#include "backend/model_error.hpp"

namespace cerebellum {

// each error drawn uniformly within its range; a zero range leaves that part exact
struct ModelErrorRanges {
  double mass_fraction = 0.0;            // a payload of up to +- this fraction of the robot's mass
  double com_offset_m = 0.0;             // the trunk's centre of mass moved up to +- this along each axis
  double friction_min = 0.0;             // the feet's friction within [min, max]; 0, 0: the model's own
  double friction_max = 0.0;
  double motor_strength_fraction = 0.0;  // every motor's strength 1 +- up to this
  double actuation_delay_min_s = 0.0;    // the actuation delay within [min, max], whole physics steps
  double actuation_delay_max_s = 0.0;
  double sensor_noise_scale = 1.0;       // the sensor noise's deviations times this (not drawn)
};

// the same seed gives the same draw; a stream of its own, apart from the noise's and the soak's
ModelError draw_model_error(const ModelErrorRanges& ranges, unsigned seed);

// one line for a run's log: "payload +0.83 kg, CoM (+0.011, -0.004, +0.019) m, ..."
std::string describe_model_error(const ModelError& error);

}  // namespace cerebellum
