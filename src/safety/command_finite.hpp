// NaN/Inf in a joint command: the one check every stage that receives a command uses.
#pragma once

#include <cstddef>
#include <optional>

#include "core/types.hpp"

namespace cerebellum {

// the fields of a JointCommand, in the order they are checked
enum class CommandField { QDes, QdDes, Kp, Kd, TauFf };

double command_value(const JointCommand& command, std::size_t joint, CommandField field);

// the first field of this joint that is NaN or Inf, if any
std::optional<CommandField> non_finite_field(const JointCommand& command, std::size_t joint);

// every number of every joint is finite
bool command_is_finite(const JointCommand& command);

}  // namespace cerebellum
