#include "cli/virtual_pad_script.hpp"

#include <sstream>
#include <stdexcept>

#include "core/number_text.hpp"

namespace cerebellum {

std::vector<VirtualPadEvent> parse_virtual_pad_script(const std::string& text) {
  std::vector<VirtualPadEvent> events;
  std::istringstream lines(text);
  std::string line;
  for (int number = 1; std::getline(lines, line); ++number) {
    line = line.substr(0, line.find('#'));
    std::istringstream words(line);
    std::vector<std::string> fields;
    for (std::string word; words >> word;) fields.push_back(word);
    if (fields.empty()) continue;
    const auto fail = [&](const std::string& why) {
      throw std::invalid_argument("virtual pad script line " + std::to_string(number) + ": " + why);
    };
    VirtualPadEvent event;
    const std::optional<double> at_s = finite_number(fields[0]);
    if (!at_s || *at_s < 0.0) fail("'" + fields[0] + "' is not a time in seconds");
    if (!events.empty() && *at_s < events.back().at_s) fail("times must not go back");
    event.at_s = *at_s;
    if (fields.size() == 2 && (fields[1] == "plug" || fields[1] == "unplug")) {
      event.kind = fields[1] == "plug" ? VirtualPadEvent::Kind::Plug : VirtualPadEvent::Kind::Unplug;
      events.push_back(event);
      continue;
    }
    if (fields.size() != 3) fail("expected '<seconds> <control> <value>', '<seconds> plug' or '<seconds> unplug'");
    const std::optional<double> value = finite_number(fields[2]);
    if (!value || *value < -1.0 || *value > 1.0) fail("'" + fields[2] + "' is not a value in [-1, 1]");
    event.control = fields[1];
    event.value = *value;
    events.push_back(event);
  }
  return events;
}

}  // namespace cerebellum
