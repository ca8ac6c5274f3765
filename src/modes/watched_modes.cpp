#include "modes/watched_modes.hpp"

#include "control/locomotion/gait_table.hpp"
#include "modes/qp_stand_mode.hpp"

namespace cerebellum {

HighLevelCommand command_after_landing(const HighLevelCommand& lifted_from) {
  HighLevelCommand command = lifted_from;
  command.duration = 0;
  command.vel_des = {};
  command.contact = 0x0F;
  if (lifted_from.mode == static_cast<int>(ModeId::Locomotion)) {
    command.gait_id = resting_gait_of(lifted_from.gait_id);
  } else if (lifted_from.mode == static_cast<int>(ModeId::QpStand)) {
    // mode 3 starts from the level stand: the last command's values, taken as increments from it,
    // restore an absolute pose (3, 0) and come close to an incremental one, at the slower speed
    command.gait_id = kQpStandIncrementalGait;
  } else {
    command = HighLevelCommand{};
    command.mode = static_cast<int>(ModeId::QpStand);
    command.gait_id = kQpStandIncrementalGait;
  }
  return command;
}

}  // namespace cerebellum
