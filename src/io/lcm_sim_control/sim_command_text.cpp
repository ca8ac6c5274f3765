#include "io/lcm_sim_control/sim_command_text.hpp"

#include <cmath>
#include <sstream>
#include <vector>

#include "core/number_text.hpp"

namespace cerebellum {
namespace {

// 17 significant digits: a push reads back as the same doubles
std::string format_number(double value) { return number_text(value, 17); }

}  // namespace

SimCommand parse_sim_command(const std::string& text) {
  SimCommand command;
  if (text.size() > kSimCommandTextMaxBytes) {
    command.error = "command longer than " + std::to_string(kSimCommandTextMaxBytes) + " bytes";
    return command;
  }
  std::istringstream in(text);
  std::vector<std::string> words;
  for (std::string word; in >> word;) words.push_back(word);
  if (words.empty()) {
    command.error = "empty command (accepted: push FX FY FZ DURATION_S, fault ...)";
    return command;
  }
  if (words[0] == "fault" && words.size() > 1 && words[1] == "link") {
    LinkFaultParse parsed = parse_link_fault(std::vector<std::string>(words.begin() + 1, words.end()));
    command.link = parsed.request;
    command.error = parsed.error;
    return command;
  }
  if (words[0] == "fault") {
    FaultParse parsed = parse_fault(std::vector<std::string>(words.begin() + 1, words.end()));
    command.fault = parsed.request;
    command.error = parsed.error;
    return command;
  }
  if (words[0] != "push") {
    command.error = "unknown command '" + words[0].substr(0, 32) + "' (accepted: push FX FY FZ DURATION_S, fault ...)";
    return command;
  }
  if (words.size() != 5) {
    command.error = "push takes 4 numbers, FX FY FZ (N) and DURATION_S, got " + std::to_string(words.size() - 1);
    return command;
  }
  static const char* const kNames[] = {"FX", "FY", "FZ", "DURATION_S"};
  double values[4] = {};
  for (int k = 0; k < 4; ++k) {
    const std::optional<double> value = finite_number(words[k + 1]);
    if (!value) {
      command.error =
          std::string("push ") + kNames[k] + " must be a finite number, got '" + words[k + 1].substr(0, 32) + "'";
      return command;
    }
    values[k] = *value;
  }
  const double magnitude_n = std::sqrt(values[0] * values[0] + values[1] * values[1] + values[2] * values[2]);
  if (magnitude_n > kPushForceMaxN) {
    command.error =
        "push force " + format_number(magnitude_n) + " N is above the limit of " + format_number(kPushForceMaxN) + " N";
    return command;
  }
  if (!(values[3] > 0.0 && values[3] <= kPushDurationMaxS)) {
    command.error =
        "push DURATION_S must be in (0, " + format_number(kPushDurationMaxS) + "] s, got " + words[4].substr(0, 32);
    return command;
  }
  command.push = ForcePulse{{values[0], values[1], values[2]}, values[3]};
  return command;
}

std::string push_command_text(const ForcePulse& pulse) {
  return "push " + format_number(pulse.force_n[0]) + " " + format_number(pulse.force_n[1]) + " " +
         format_number(pulse.force_n[2]) + " " + format_number(pulse.duration_s);
}

std::string fault_command_text(const FaultRequest& request) { return "fault " + fault_text(request); }

std::string fault_command_text(const LinkFaultRequest& request) { return "fault " + link_fault_text(request); }

}  // namespace cerebellum
