// What the machine watches in the modes that stand on their feet (3, 11, 21): the body tipping
// over (ori_error -> protective stop until a recovery stand) and the robot being picked up.
#pragma once

#include <cmath>

#include "core/leg_kinematics.hpp"
#include "core/robot_state.hpp"
#include "modes/high_level_command.hpp"

namespace cerebellum {

inline constexpr double kOrientationErrorRad = 1.3;

inline bool watches_body(ModeId mode) {
  return mode == ModeId::QpStand || mode == ModeId::Locomotion || mode == ModeId::PoseControl;
}

// |roll| or |pitch| at or beyond the limit
inline bool orientation_error(const RobotState& state, double limit_rad = kOrientationErrorRad) {
  return std::abs(state.rpy.x()) >= limit_rad || std::abs(state.rpy.y()) >= limit_rad;
}

// the foot workspace of the interface: L = 0.294 m leg, abad = 0.094 m offset
struct FootWorkspace {
  double forward_m = 0.294 * 0.8660254037844386;                          // L sin 60 deg
  double lateral_m = 0.294 * std::sin(0.68) + 0.094 * std::cos(0.68);     // L sin 0.68 + abad cos 0.68
  double lowest_m = -std::sqrt(0.294 * 0.294 + 0.094 * 0.094);
  double highest_m = -0.294 / 6.0;
};

// footpos_error bits: bit 3 * leg + axis (0 forward, 1 lateral, 2 vertical) for a foot outside
// its workspace, measured from its abad joint in the body frame
inline int foot_position_error_bits(const RobotState& state, const FootWorkspace& workspace = {}) {
  int bits = 0;
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
    const Vec3 p = state.foot_position_body[leg] - hip_position(leg);
    if (std::abs(p.x()) > workspace.forward_m) bits |= 1 << (3 * leg);
    if (std::abs(p.y()) > workspace.lateral_m) bits |= 1 << (3 * leg + 1);
    if (p.z() < workspace.lowest_m || p.z() > workspace.highest_m) bits |= 1 << (3 * leg + 2);
  }
  return bits;
}

// the foot workspace is watched while walking: the other standing modes lift feet on purpose
inline bool watches_feet(ModeId mode) { return mode == ModeId::Locomotion; }

}  // namespace cerebellum
