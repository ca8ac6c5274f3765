// Which mode may follow which (the interface's Appendix Table 1); anything else is BAN_TRANS.
#pragma once

#include "core/high_level_command.hpp"

namespace cerebellum {

bool transition_allowed(ModeId from, ModeId to);
// true for the mode ids the interface defines (not whether this MC implements them)
bool is_known_mode(int mode);

}  // namespace cerebellum
