#include "control/pose_reach.hpp"

#include "core/leg_kinematics.hpp"
#include "core/robot_model.hpp"

namespace cerebellum {

bool feet_reachable(const BodyPose& pose, const Footholds& footholds, const LegMask& feet, double margin_rad) {
  const Eigen::Matrix3d rotation = rotation_from_rpy(pose.rpy);
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
    if (!feet[leg]) continue;
    const LegIkResult ik = inverse_kinematics_in_body(leg, rotation.transpose() * (footholds[leg] - pose.position));
    if (!ik.reachable) return false;
    for (std::size_t k = 0; k < kJointsPerLeg; ++k) {
      const robot::JointRange range = robot::joint_range(kJointsPerLeg * leg + k);
      const double q = ik.q[static_cast<Eigen::Index>(k)];
      if (q < range.lower + margin_rad || q > range.upper - margin_rad) return false;
    }
  }
  return true;
}

BodyPose blend(const BodyPose& from, const BodyPose& to, double fraction) {
  BodyPose pose;
  pose.rpy = from.rpy + fraction * (to.rpy - from.rpy);
  pose.position = from.position + fraction * (to.position - from.position);
  return pose;
}

double reachable_fraction(const BodyPose& from, const BodyPose& to, const Footholds& footholds, const LegMask& feet,
                          double margin_rad) {
  if (feet_reachable(to, footholds, feet, margin_rad)) return 1.0;
  if (!feet_reachable(from, footholds, feet, margin_rad)) return 0.0;
  double low = 0.0;
  double high = 1.0;
  while (high - low > 1e-3) {
    const double mid = 0.5 * (low + high);
    (feet_reachable(blend(from, to, mid), footholds, feet, margin_rad) ? low : high) = mid;
  }
  return low;
}

}  // namespace cerebellum
