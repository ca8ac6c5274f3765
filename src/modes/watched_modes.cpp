#include "modes/watched_modes.hpp"

namespace cerebellum {

HighLevelCommand command_after_landing(const HighLevelCommand& lifted_from) {
  HighLevelCommand command = lifted_from;
  command.duration = 0;
  command.vel_des = {};
  command.contact = 0x0F;
  if (lifted_from.mode == static_cast<int>(ModeId::Locomotion)) {
    command.gait_id = lifted_from.gait_id <= 30 ? 1 : 31;
  } else if (lifted_from.mode == static_cast<int>(ModeId::QpStand)) {
    command.gait_id = 1;
  } else {
    command = HighLevelCommand{};
    command.mode = static_cast<int>(ModeId::QpStand);
    command.gait_id = 1;
  }
  return command;
}

}  // namespace cerebellum
