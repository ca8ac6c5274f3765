// A named motion as a file of our own (docs/motions.md): an id, a name and [[step]] tables of
// robot_control_cmd fields in the seed's sequential-motion format, each run for its duration.
//
//   id = 2
//   name = "shake right hand"
//   [[step]]
//   mode = 21
//   gait_id = 2
//   contact = 0b1110
//   foot_pose = [0.12, 0.0, 0.12, 0.0, 0.0, 0.0]
//   duration = 1500
//
// A motion may bring its own user gait, run by its steps of mode 11 gait 110:
//   user_gait = { definition = "../user_gaits/moonwalk_def.toml", parameters = "..." }
// (paths relative to the motion file; the parser keeps them as written).
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

#include "modes/motion.hpp"

namespace cerebellum {

inline constexpr std::size_t kMaxMotionFileBytes = 64 * 1024;
inline constexpr std::size_t kMaxMotionSteps = 200;
inline constexpr int kMaxMotionStepMs = 60000;
inline constexpr std::size_t kMaxMotionNameLength = 64;

struct MotionFileParse {
  std::optional<Motion> motion;
  std::string error;  // what is wrong and where (line, key, expected) when there is no motion
};

// the motion of a file's text; its origin is left empty for the caller
MotionFileParse parse_motion_file(std::string_view text);

}  // namespace cerebellum
