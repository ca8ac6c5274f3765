#include "cli/diagnostics_listener.hpp"

#include <lcm/lcm-cpp.hpp>

#include <cstdio>

#include "io/lcm_common/lcm_url.hpp"

namespace cerebellum {

DiagnosticsListener::DiagnosticsListener(const std::string& url) : lcm_(open_lcm_url(url, "status")) {
  lcm_->subscribe("mc_diagnostics", &DiagnosticsListener::on_message, this);
}

DiagnosticsListener::~DiagnosticsListener() = default;

void DiagnosticsListener::on_message(const lcm::ReceiveBuffer* buffer, const std::string&) {
  mc_diagnostics_lcmt message;
  // a packet that does not decode is not the MC's: ignored (status only shows)
  if (message.decode(buffer->data, 0, static_cast<int>(buffer->data_size)) ==
      static_cast<int>(buffer->data_size)) {
    newest_ = message;
  }
}

std::optional<mc_diagnostics_lcmt> DiagnosticsListener::poll() {
  handle_pending(*lcm_, 0);
  std::optional<mc_diagnostics_lcmt> taken;
  taken.swap(newest_);
  return taken;
}

std::string describe_diagnostics(const mc_diagnostics_lcmt& m) {
  char text[512];
  int used = std::snprintf(text, sizeof text,
                           "mc: loop period p50 %.2f / p99 %.2f / max %.2f ms (%d ticks, %lld late substeps)",
                           m.loop_period_ms[0], m.loop_period_ms[1], m.loop_period_ms[2], m.ticks,
                           static_cast<long long>(m.late_substeps));
  if (m.ticks > 0 && m.loop_period_ms[2] == 0.0f) {
    used += std::snprintf(text + used, sizeof text - used, " [lockstep: no wall-clock period]");
  }
  if (m.link) {
    used += std::snprintf(text + used, sizeof text - used, " | %s link: state age p50 %.2f / p99 %.2f / max %.2f ms",
                          m.robot.c_str(), m.state_age_ms[0], m.state_age_ms[1], m.state_age_ms[2]);
    if (m.round_trip_ms[2] > 0.0f) {
      used += std::snprintf(text + used, sizeof text - used, ", round trip p50 %.2f / p99 %.2f / max %.2f ms",
                            m.round_trip_ms[0], m.round_trip_ms[1], m.round_trip_ms[2]);
    } else {
      used += std::snprintf(text + used, sizeof text - used, ", no round trip (the link echoes nothing)");
    }
    std::snprintf(text + used, sizeof text - used, ", %lld losses, %lld states refused, %lld frames late",
                  static_cast<long long>(m.link_losses), static_cast<long long>(m.states_refused),
                  static_cast<long long>(m.frames_late));
  } else {
    std::snprintf(text + used, sizeof text - used, " | robot %s: no link (simulated)", m.robot.c_str());
  }
  return text;
}

}  // namespace cerebellum
