// The contacts the control stage plans (a gait's schedule), handed to the estimator by the loop
// at the next tick: the estimator trusts the feet the plan puts on the ground.
#pragma once

#include <array>
#include <optional>

#include "core/joint_layout.hpp"

namespace cerebellum {

// one leg's place in a gait, as a gait scheduler plans it
struct LegContactPlan {
  double probability = 0.0;   // 0..1 that the foot is on the ground now (0 in swing)
  double stance_phase = 0.0;  // 0..1 through the current stance; ignored in swing
};
using ContactSchedule = std::array<LegContactPlan, kNumLegs>;

// no value: nothing plans the contacts (standing, low-level control); the estimator then
// judges contacts from its own force estimate
using ContactPlan = std::optional<ContactSchedule>;

}  // namespace cerebellum
