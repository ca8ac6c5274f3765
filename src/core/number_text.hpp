// Numbers as people and command texts write them: one reader and one writer for every text
// grammar of the project (command-line options, sim_command texts, fault words).
#pragma once

#include <optional>
#include <string>

namespace cerebellum {

// the whole text as a finite number, or nothing (empty text, trailing characters, NaN, Inf)
std::optional<double> finite_number(const std::string& text);

// printf's %.<significant_digits>g: 17 digits read back as the same double, 12 read back as what a
// person typed
std::string number_text(double value, int significant_digits = 17);

}  // namespace cerebellum
