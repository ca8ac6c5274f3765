// `cerebellum status --diagnostics`: the MC's own figures (mc_diagnostics, once a second) as they
// arrive, and the line that shows them. The status command's thread polls; no thread of its own.
#pragma once

#include <memory>
#include <optional>
#include <string>

#include "mc_diagnostics_lcmt.hpp"

namespace lcm {
class LCM;
struct ReceiveBuffer;
}  // namespace lcm

namespace cerebellum {

class DiagnosticsListener {
 public:
  // url: the MC's high-level response url. Throws std::runtime_error naming a url LCM cannot open
  explicit DiagnosticsListener(const std::string& url);
  ~DiagnosticsListener();
  DiagnosticsListener(const DiagnosticsListener&) = delete;
  DiagnosticsListener& operator=(const DiagnosticsListener&) = delete;

  // what arrived since the last call: the newest message, or nothing
  std::optional<mc_diagnostics_lcmt> poll();

 private:
  void on_message(const lcm::ReceiveBuffer* buffer, const std::string& channel);

  std::unique_ptr<lcm::LCM> lcm_;
  std::optional<mc_diagnostics_lcmt> newest_;
};

// "mc: loop period p50 2.00 / p99 2.41 / max 3.10 ms (500 ticks, 0 late substeps) | cyberdog2_motor_sdk
// link: state age p50 ..., 0 losses, 0 states refused, 0 frames late"
std::string describe_diagnostics(const mc_diagnostics_lcmt& message);

}  // namespace cerebellum
