#include "core/number_text.hpp"

#include <cmath>
#include <cstdio>

namespace cerebellum {

std::optional<double> finite_number(const std::string& text) {
  std::size_t used = 0;
  double value = 0.0;
  try {
    value = std::stod(text, &used);
  } catch (const std::exception&) {
    return std::nullopt;
  }
  if (used != text.size() || !std::isfinite(value)) return std::nullopt;
  return value;
}

std::string number_text(double value, int significant_digits) {
  char text[40];
  std::snprintf(text, sizeof text, "%.*g", significant_digits, value);
  return text;
}

}  // namespace cerebellum
