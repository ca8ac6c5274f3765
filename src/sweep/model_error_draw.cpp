#include "sweep/model_error_draw.hpp"

#include <cstdio>
#include <random>

#include "core/robot_model.hpp"

namespace cerebellum {

ModelError draw_model_error(const ModelErrorRanges& ranges, unsigned seed) {
  // "model" in ASCII tells this stream apart from the noise's and the soak's of the same seed
  std::seed_seq sequence{seed, 0x6d6f64u, 0x656cu};
  std::mt19937 rng(sequence);
  // every part drawn in a fixed order, whether its range is zero or not: a range widened later
  // does not change the other parts' draws
  const auto within = [&](double low, double high) {
    const double u = std::uniform_real_distribution<double>(0.0, 1.0)(rng);
    return low + (high - low) * u;
  };
  ModelError error;
  error.added_mass_kg = within(-ranges.mass_fraction, ranges.mass_fraction) * robot::kTotalMassKg;
  for (double& offset : error.com_offset_m) offset = within(-ranges.com_offset_m, ranges.com_offset_m);
  error.foot_friction = within(ranges.friction_min, ranges.friction_max);
  error.motor_strength_scale = 1.0 + within(-ranges.motor_strength_fraction, ranges.motor_strength_fraction);
  // whole milliseconds (the physics step) come out of the backend's rounding
  error.actuation_delay_s = within(ranges.actuation_delay_min_s, ranges.actuation_delay_max_s);
  return error;
}

std::string describe_model_error(const ModelError& error) {
  char friction[32] = "as modelled";
  if (error.foot_friction > 0.0) std::snprintf(friction, sizeof friction, "%.2f", error.foot_friction);
  char line[256];
  std::snprintf(line, sizeof line,
                "payload %+.2f kg, CoM moved (%+.3f, %+.3f, %+.3f) m, foot friction %s, motor strength x%.3f, "
                "actuation delay %.1f ms",
                error.added_mass_kg, error.com_offset_m[0], error.com_offset_m[1], error.com_offset_m[2], friction,
                error.motor_strength_scale, 1e3 * error.actuation_delay_s);
  return line;
}

}  // namespace cerebellum
