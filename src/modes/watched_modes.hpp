// The state machine's side of the body watch (safety/body_watch, safety/lift_detector say what is
// wrong): which modes are watched, and where a lifted robot resumes once it is set down.
#pragma once

#include "core/high_level_command.hpp"

namespace cerebellum {

// the modes that stand on their feet (3, 11, 21, the motions made of them, and the jumps, which
// land on them): tipping over and being picked up are watched (a jump in the air is not lifted:
// Mode::airborne)
inline bool watches_body(ModeId mode) {
  return mode == ModeId::QpStand || mode == ModeId::Locomotion || mode == ModeId::PoseControl ||
         mode == ModeId::Motion || mode == ModeId::Jump3d || mode == ModeId::ForceJump;
}

// the foot workspace is watched while walking: the other standing modes lift feet on purpose
inline bool watches_feet(ModeId mode) { return mode == ModeId::Locomotion; }

// the command the MC resumes with when the robot is set down after a lift in `lifted_from`:
// QP stand and locomotion stand as they were (walking gaits stand first), pose control -> QP stand
HighLevelCommand command_after_landing(const HighLevelCommand& lifted_from);

}  // namespace cerebellum
