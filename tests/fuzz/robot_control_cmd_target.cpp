// robot_control_cmd packets (LCM: fingerprint + fixed-size body): the decoder never reads past
// the packet and refuses what is not exactly one message.
#include "fuzz_target.hpp"
#include "io/lcm_highlevel/highlevel_wire.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  cerebellum::HighLevelCommand command;
  (void)cerebellum::decode_robot_control_cmd(data, size, command);
  std::string text;
  (void)cerebellum::decode_file_send(data, size, text);
  FUZZ_CHECK(text.size() <= size);
  return 0;
}
