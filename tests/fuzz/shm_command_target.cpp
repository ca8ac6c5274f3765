// Shared-memory command frames (lowlevel.h leg_control_t[4], written by any local process): a
// frame is taken only when every number is within the command rules (the translation of
// io/shm_lowlevel, then the check the source of lowlevel/shm applies).
#include <cmath>
#include <cstring>

#include "fuzz_target.hpp"
#include "io/shm_lowlevel/shm_codec.hpp"
#include "lowlevel/shm/shm_command_rules.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  leg_control_t legs[cerebellum::kNumLegs];
  if (size < sizeof legs) return 0;
  std::memcpy(legs, data, sizeof legs);
  const cerebellum::JointCommand command = cerebellum::decode_shm_command(legs);
  const cerebellum::CommandLimits limits;
  const cerebellum::ShmCommandCheck check = cerebellum::check_shm_command(command, limits);
  if (check.ok()) {
    for (std::size_t j = 0; j < command.q_des.size(); ++j) {
      FUZZ_CHECK(std::isfinite(command.q_des[j]) && std::isfinite(command.qd_des[j]) && std::isfinite(command.kp[j]) &&
                 std::isfinite(command.kd[j]) && std::isfinite(command.tau_ff[j]));
      FUZZ_CHECK(command.kp[j] >= 0.0 && command.kp[j] <= limits.kp_max);
    }
  }
  return 0;
}
