#include "modes/locomotion_gait.hpp"

#include <stdexcept>

namespace cerebellum {

void GaitRegistry::add(int gait_id, LocomotionGait& gait) {
  if (gait_id < 0 || gait_id > kMaxGaitId) throw std::out_of_range("gait id must be in 0..127");
  gaits_[static_cast<std::size_t>(gait_id)] = &gait;
}

LocomotionGait* GaitRegistry::find(int gait_id) const {
  if (gait_id < 0 || gait_id > kMaxGaitId) return nullptr;
  return gaits_[static_cast<std::size_t>(gait_id)];
}

}  // namespace cerebellum
