#include "safety/command_finite.hpp"

#include <cmath>

namespace cerebellum {

double command_value(const JointCommand& command, std::size_t joint, CommandField field) {
  switch (field) {
    case CommandField::QDes: return command.q_des[joint];
    case CommandField::QdDes: return command.qd_des[joint];
    case CommandField::Kp: return command.kp[joint];
    case CommandField::Kd: return command.kd[joint];
    case CommandField::TauFf: return command.tau_ff[joint];
  }
  return 0.0;
}

std::optional<CommandField> non_finite_field(const JointCommand& command, std::size_t joint) {
  for (CommandField field :
       {CommandField::QDes, CommandField::QdDes, CommandField::Kp, CommandField::Kd, CommandField::TauFf}) {
    if (!std::isfinite(command_value(command, joint, field))) return field;
  }
  return std::nullopt;
}

bool command_is_finite(const JointCommand& command) {
  for (std::size_t i = 0; i < kNumJoints; ++i) {
    if (non_finite_field(command, i)) return false;
  }
  return true;
}

}  // namespace cerebellum
