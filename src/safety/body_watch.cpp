#include "safety/body_watch.hpp"

#include <algorithm>
#include <cmath>

#include "core/leg_kinematics.hpp"
#include "core/robot_model.hpp"

namespace cerebellum {
namespace {

constexpr double kLegM = robot::kInterfaceLegLengthM;
constexpr double kAbadM = robot::kAbadLength;
// the workspace's abad angle is the abad joint's limit
constexpr double kAbadLimitRad = robot::kAbadRange.upper;

}  // namespace

bool orientation_error(const RobotState& state, double limit_rad) {
  return std::abs(state.rpy.x()) >= limit_rad || std::abs(state.rpy.y()) >= limit_rad;
}

double FootWorkspace::default_forward_m() { return kLegM * std::sin(robot::deg(60.0)); }
double FootWorkspace::default_lateral_m() { return kLegM * std::sin(kAbadLimitRad) + kAbadM * std::cos(kAbadLimitRad); }
double FootWorkspace::default_lowest_m() { return -std::sqrt(kLegM * kLegM + kAbadM * kAbadM); }
double FootWorkspace::default_highest_m() { return -kLegM / 6.0; }

int foot_position_error_bits(const RobotState& state, const FootWorkspace& workspace) {
  int bits = 0;
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
    const Vec3 p = state.foot_position_body[leg] - hip_position(leg);
    if (std::abs(p.x()) > workspace.forward_m) bits |= 1 << (3 * leg);
    if (std::abs(p.y()) > workspace.lateral_m) bits |= 1 << (3 * leg + 1);
    if (p.z() < workspace.lowest_m || p.z() > workspace.highest_m) bits |= 1 << (3 * leg + 2);
  }
  return bits;
}

Vec3 clamp_into_foot_workspace(std::size_t leg, const Vec3& foot_body, const FootWorkspace& workspace,
                               double margin_m) {
  Vec3 p = foot_body - hip_position(leg);
  const double forward = std::max(workspace.forward_m - margin_m, 0.0);
  const double lateral = std::max(workspace.lateral_m - margin_m, 0.0);
  p.x() = std::clamp(p.x(), -forward, forward);
  p.y() = std::clamp(p.y(), -lateral, lateral);
  p.z() = std::clamp(p.z(), workspace.lowest_m + margin_m,
                     std::max(workspace.highest_m - margin_m, workspace.lowest_m + margin_m));
  return p + hip_position(leg);
}

SafetyReport check_body(const RobotState& state, bool check_feet, const BodyWatchLimits& limits) {
  SafetyReport report;
  report.orientation_error = orientation_error(state, limits.orientation_limit_rad);
  report.footpos_error = check_feet ? foot_position_error_bits(state, limits.workspace) : 0;
  return report;
}

}  // namespace cerebellum
