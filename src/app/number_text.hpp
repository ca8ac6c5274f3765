// Numbers typed by a user on the command line.
#pragma once

#include <optional>
#include <string>

namespace cerebellum {

// the whole text as a finite number, or nothing (empty text, trailing characters, NaN, Inf)
std::optional<double> finite_number(const std::string& text);

// an option's value as a finite number; throws std::invalid_argument
// "<option>: '<text>' is not <accepted>" otherwise
double option_number(const std::string& option, const std::string& text, const std::string& accepted);

}  // namespace cerebellum
