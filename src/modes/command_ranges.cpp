#include "modes/command_ranges.hpp"

#include <algorithm>

#include "core/joint_layout.hpp"

namespace cerebellum {

double Range::clamp(double value) const { return std::clamp(value, lower, upper); }

const VelocityLimits* locomotion_velocity_limits(int gait_id) {
  static const VelocityLimits pronk{{-0.10, -0.15, -0.50}, {0.20, 0.15, 0.50}};
  static const VelocityLimits slow_trot{{-0.60, -0.2, -1.30}, {0.60, 0.2, 1.30}};
  static const VelocityLimits walk_dog{{-0.65, -0.4, -0.80}, {0.65, 0.4, 0.80}};
  static const VelocityLimits bound{{-0.3, -0.3, -1.5}, {0.3, 0.3, 1.5}};
  static const VelocityLimits medium_trot{{-1.2, -0.4, -2.25}, {1.2, 0.4, 2.25}};
  static const VelocityLimits flying_trot{{-1.2, -0.55, -2.5}, {1.6, 0.55, 2.5}};
  static const VelocityLimits variable_trot{{-1.2, -0.6, -2.5}, {1.6, 0.6, 2.5}};
  switch (gait_id) {
    case 2: return &pronk;
    case 27: return &slow_trot;
    case 4: return &walk_dog;
    case 7: return &bound;
    case 3: return &medium_trot;
    case 10: return &flying_trot;
    case 26: return &variable_trot;
    default: return nullptr;
  }
}

int lifted_leg_from_contact(int contact) {
  const int down = contact & 0x0F;
  if (down == 0 || down == 0x0F) return kNoLiftedLeg;
  for (int leg = 0; leg < static_cast<int>(kNumLegs); ++leg) {
    if (down == (0x0F & ~(1 << leg))) return leg;
  }
  return kInvalidContact;
}

Eigen::Vector3d lifted_foot_offset(const HighLevelCommand& command, int leg, const FootOffsetRanges& ranges) {
  const std::size_t first = is_front_leg(static_cast<std::size_t>(leg)) ? 0 : 3;
  const Eigen::Vector3d given(command.foot_pose[first], command.foot_pose[first + 1], command.foot_pose[first + 2]);
  if (given.isZero()) return {0.0, 0.0, ranges.default_lift_m};
  return {ranges.x.clamp(given.x()), ranges.y.clamp(given.y()), ranges.z.clamp(given.z())};
}

}  // namespace cerebellum
