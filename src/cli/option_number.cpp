#include "cli/option_number.hpp"

#include <stdexcept>

namespace cerebellum {

double option_number(const std::string& option, const std::string& text, const std::string& accepted) {
  const std::optional<double> value = finite_number(text);
  if (!value) throw std::invalid_argument(option + ": '" + text + "' is not " + accepted);
  return *value;
}

}  // namespace cerebellum
