// AlienGo HighCmd datagrams: the decoder as the bytes come; then the same fields sent with a
// correct CRC (to reach past the check): decoded unless a number is not finite, and a decoded
// command streamed through the sport session hands the MC only finite commands.
#include <cmath>
#include <cstring>

#include "fuzz_target.hpp"
#include "modes/aliengo_session.hpp"
#include "io/udp_aliengo/aliengo_wire.hpp"

namespace {

bool finite(const cerebellum::HighLevelCommand& c) {
  for (float v : c.vel_des)
    if (!std::isfinite(v)) return false;
  for (float v : c.rpy_des)
    if (!std::isfinite(v)) return false;
  for (float v : c.pos_des)
    if (!std::isfinite(v)) return false;
  for (float v : c.step_height)
    if (!std::isfinite(v)) return false;
  return true;
}

// the command fields at their HighCmd offsets
cerebellum::AlienGoCommand fields_of(const std::uint8_t* frame) {
  cerebellum::AlienGoCommand c;
  float v[10];
  std::memcpy(v, frame + 13, sizeof v);
  c.mode = frame[10];
  c.gait_type = frame[11];
  c.speed_level = frame[12];
  c.foot_raise_m = v[0];
  c.body_height_m = v[1];
  c.position = {v[2], v[3]};
  c.rpy = {v[4], v[5], v[6]};
  c.velocity = {v[7], v[8]};
  c.yaw_speed = v[9];
  return c;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace cerebellum;
  AlienGoCommand decoded;
  (void)decode_high_cmd(data, size, decoded);
  if (size != kHighCmdBytes) return 0;

  std::uint8_t frame[kHighCmdBytes];
  encode_high_cmd(fields_of(data), frame);
  const AlienGoDecode result = decode_high_cmd(frame, sizeof frame, decoded);
  FUZZ_CHECK(result == AlienGoDecode::Ok || result == AlienGoDecode::NonFinite);
  if (result != AlienGoDecode::Ok) return 0;

  AlienGoSession session;
  RobotState state;
  state.valid = true;
  state.position_world = {0.3, -0.2, 0.25};
  for (int mc_mode : {0, 11, 12}) {
    const AlienGoStep step = session.on_command(decoded, state, mc_mode, 100, 0.002 * mc_mode);
    if (step.submit) FUZZ_CHECK(finite(*step.submit));
  }
  const AlienGoStep silent = session.on_silence(state, 11, 100, 1.0);
  if (silent.submit) FUZZ_CHECK(finite(*silent.submit));
  return 0;
}
