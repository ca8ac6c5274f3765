// Which pair of legs, if any, stands with no other foot down: a bound's front or rear stance. The
// MPC lowers its yaw weight there, and a gait's entry point is chosen by how wide that pair stands.
#pragma once

#include <array>
#include <cstddef>

#include "core/joint_layout.hpp"

namespace cerebellum {

enum class LonePair { None, Front, Rear };

constexpr LonePair lone_pair(const std::array<bool, kNumLegs>& stance) {
  constexpr auto fr = static_cast<std::size_t>(Leg::FR), fl = static_cast<std::size_t>(Leg::FL);
  constexpr auto rr = static_cast<std::size_t>(Leg::RR), rl = static_cast<std::size_t>(Leg::RL);
  const bool front_any = stance[fr] || stance[fl];
  const bool rear_any = stance[rr] || stance[rl];
  if (stance[fr] && stance[fl] && !rear_any) return LonePair::Front;
  if (stance[rr] && stance[rl] && !front_any) return LonePair::Rear;
  return LonePair::None;
}

}  // namespace cerebellum
