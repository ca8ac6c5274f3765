#include "loop/timed_fault_entry.hpp"

#include "loop/yaml_section.hpp"

namespace cerebellum {

TimedFault read_timed_fault(const YAML::Node& node, const std::string& file, const std::string& entry_name,
                            const std::string& kind, double latest_s, double max_duration_s) {
  const SectionReader entry(node, file, entry_name, {"at_s", "fault", "duration_s"}, kind);
  if (!entry.has("at_s")) entry.fail(entry_name, "needs at_s (simulated seconds from the start)");
  if (!entry.has("fault")) entry.fail(entry_name, "needs fault (for example: motor 3 disconnected)");
  TimedFault timed;
  entry.number("at_s", timed.at_s, 0.0, latest_s);
  std::string words;
  entry.text("fault", words);
  const FaultParse parsed = parse_fault(words);
  if (!parsed.request) entry.fail(entry_name + ".fault", parsed.error);
  timed.request = *parsed.request;
  if (entry.has("duration_s")) {
    if (timed.request.kind == FaultKind::Clear) entry.fail(entry_name + ".duration_s", "is not taken by a clear");
    entry.number("duration_s", timed.request.duration_s, 1e-3, max_duration_s);
  }
  return timed;
}

}  // namespace cerebellum
