#include "loop/locomotion_limits_section.hpp"

#include <set>

#include "control/locomotion/gait_table.hpp"
#include "loop/yaml_section.hpp"

namespace cerebellum {
namespace {

std::string gait_key(const GaitSpec& gait) { return "gait_" + std::to_string(gait.id); }

// one gait's limits, symmetric sideways and in turning as the table's are
void read_gait(const SectionReader& s, VelocityLimits& limits) {
  double forward = limits.max.x(), backward = -limits.min.x();
  double lateral = limits.max.y(), yaw_rate = limits.max.z();
  s.number("forward_max_m_s", forward, 0.0, kExtendedForwardSpeedCeilingMPerS);
  s.number("backward_max_m_s", backward, 0.0, kExtendedForwardSpeedCeilingMPerS);
  s.number("lateral_max_m_s", lateral, 0.0, kExtendedLateralSpeedCeilingMPerS);
  s.number("yaw_rate_max_rad_s", yaw_rate, 0.0, kExtendedYawRateCeilingRadPerS);
  limits.min = {-backward, -lateral, -yaw_rate};
  limits.max = {forward, lateral, yaw_rate};
}

}  // namespace

void read_locomotion_limits_section(const YAML::Node& node, const std::string& path, LocomotionLimits& limits) {
  std::set<std::string> accepted{"step_height_max_m"};
  for (const GaitSpec& gait : kGaitTable) {
    if (gait_steps(gait)) accepted.insert(gait_key(gait));
  }
  const SectionReader section(node, path, "locomotion_limits", accepted);
  double step_height_max = limits.step_height().upper;
  section.number("step_height_max_m", step_height_max, limits.step_height().lower, kExtendedStepHeightCeilingM);
  limits.set_step_height({limits.step_height().lower, step_height_max});
  for (const GaitSpec& gait : kGaitTable) {
    const std::string key = gait_key(gait);
    if (!gait_steps(gait) || !node[key]) continue;
    VelocityLimits gait_limits = *limits.velocity(gait.id);
    read_gait(SectionReader(node[key], path, "locomotion_limits." + key,
                            {"forward_max_m_s", "backward_max_m_s", "lateral_max_m_s", "yaw_rate_max_rad_s"}),
              gait_limits);
    limits.set_velocity(gait.id, gait_limits);
  }
}

}  // namespace cerebellum
