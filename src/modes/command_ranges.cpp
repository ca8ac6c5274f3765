#include "modes/command_ranges.hpp"

#include <algorithm>

#include "core/joint_layout.hpp"

namespace cerebellum {

double Range::clamp(double value) const { return std::clamp(value, lower, upper); }

LocomotionLimits::LocomotionLimits() {
  for (std::size_t i = 0; i < kGaitTable.size(); ++i) {
    const GaitSpec& gait = kGaitTable[i];
    velocity_[i] = {Eigen::Vector3d(gait.velocity_min.data()), Eigen::Vector3d(gait.velocity_max.data())};
  }
}

const VelocityLimits* LocomotionLimits::velocity(int gait_id) const {
  const GaitSpec* gait = find_gait(gait_id);
  if (gait == nullptr || !gait_steps(*gait)) return nullptr;
  return &velocity_[static_cast<std::size_t>(gait - kGaitTable.data())];
}

bool LocomotionLimits::set_velocity(int gait_id, const VelocityLimits& limits) {
  const GaitSpec* gait = find_gait(gait_id);
  if (gait == nullptr || !gait_steps(*gait)) return false;
  velocity_[static_cast<std::size_t>(gait - kGaitTable.data())] = limits;
  return true;
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
