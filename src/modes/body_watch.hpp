// What the machine watches in the modes that stand on their feet (3, 11, 21): the body tipping
// over (ori_error -> protective stop until a recovery stand) and the robot being picked up.
#pragma once

#include <cmath>

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

}  // namespace cerebellum
