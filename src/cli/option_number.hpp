// Numbers typed by a user on the command line.
#pragma once

#include <string>

#include "core/number_text.hpp"

namespace cerebellum {

// an option's value as a finite number; throws std::invalid_argument
// "<option>: '<text>' is not <accepted>" otherwise
double option_number(const std::string& option, const std::string& text, const std::string& accepted);

}  // namespace cerebellum
