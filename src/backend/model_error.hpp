// How far the simulated robot is from the model the MC was built on: one draw of the errors a real
// robot brings (a payload, a centre of mass off its place, the floor's grip, motors weaker or
// stronger than their data sheet, actuation that arrives late), applied when the simulation is
// built. The MC is not told: it controls the robot it was tuned for.
#pragma once

#include <array>

namespace cerebellum {

// the largest actuation delay the simulation emulates (its queue of pending commands is sized by it)
inline constexpr double kMaxActuationDelayS = 0.010;

struct ModelError {
  double added_mass_kg = 0.0;                // on the trunk's centre of mass (a payload; negative: lighter)
  std::array<double, 3> com_offset_m{};      // the trunk's centre of mass moved, in the trunk's frame
  double foot_friction = 0.0;                // every foot's sliding friction against any ground; 0: the model's own
  double motor_strength_scale = 1.0;         // every driver's torque for the same command, and its limit, times this
  double actuation_delay_s = 0.0;            // a command reaches the drivers this late, in whole physics steps
  bool any() const {
    return added_mass_kg != 0.0 || com_offset_m != std::array<double, 3>{} || foot_friction != 0.0 ||
           motor_strength_scale != 1.0 || actuation_delay_s != 0.0;
  }
};

}  // namespace cerebellum
