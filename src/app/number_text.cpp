#include "app/number_text.hpp"

#include <cmath>
#include <stdexcept>

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

double option_number(const std::string& option, const std::string& text, const std::string& accepted) {
  const std::optional<double> value = finite_number(text);
  if (!value) throw std::invalid_argument(option + ": '" + text + "' is not " + accepted);
  return *value;
}

}  // namespace cerebellum
