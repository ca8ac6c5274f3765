// AlienGo HighCmd / HighState bytes <-> our types. The layout and CRC have one home: the client
// library's header (sdk/unitree_legged_sdk/include/unitree_legged_sdk/comm.h).
#pragma once

#include <cstddef>
#include <cstdint>

#include "core/high_level_command.hpp"
#include "core/robot_state.hpp"
#include "io/udp_aliengo/aliengo_feedback.hpp"
#include "modes/aliengo_command.hpp"

namespace cerebellum {

inline constexpr std::size_t kHighCmdBytes = 113;
inline constexpr std::size_t kHighStateBytes = 244;

enum class AlienGoDecode { Ok, WrongLength, BadCrc, LowLevel, NonFinite };
const char* to_string(AlienGoDecode result);

// checks length, CRC, level flag (high level 0x00 or the sport trigger 0xF0) and finite floats
AlienGoDecode decode_high_cmd(const std::uint8_t* data, std::size_t size, AlienGoCommand& out);
// a HighCmd frame with its CRC (tests, benchmarks, fuzz corpora)
void encode_high_cmd(const AlienGoCommand& command, std::uint8_t (&out)[kHighCmdBytes]);

// the HighState fields from the estimator's state; mode: the AlienGo mode the MC is in; frame: the
// sport frame (HighState.position is the odometry's trunk position in it, as mode 3's targets are)
AlienGoFeedback make_feedback(const RobotState& state, int mode, const SportFrame& frame = {});
void encode_high_state(const AlienGoFeedback& feedback, std::uint8_t (&out)[kHighStateBytes]);
// the reverse, for tests and tools: false on a wrong length or CRC
bool decode_high_state(const std::uint8_t* data, std::size_t size, AlienGoFeedback& out);

}  // namespace cerebellum
