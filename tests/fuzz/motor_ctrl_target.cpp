// motor_ctrl packets of the motor SDK: decoded or refused, never read past the packet.
#include "fuzz_target.hpp"
#include "io/lcm_motor_sdk/motor_sdk_wire.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  cerebellum::JointCommand command;
  (void)cerebellum::decode_motor_ctrl(data, size, command);
  return 0;
}
