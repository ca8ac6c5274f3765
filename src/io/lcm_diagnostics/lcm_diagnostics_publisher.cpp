#include "io/lcm_diagnostics/lcm_diagnostics_publisher.hpp"

#include <lcm/lcm-cpp.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "io/lcm_common/lcm_url.hpp"
#include "io/lcm_diagnostics/window_figures.hpp"
#include "mc_diagnostics_lcmt.hpp"

namespace cerebellum {
namespace {

constexpr const char* kChannel = "mc_diagnostics";

void put_ms(const WindowFigures& figures, float (&out)[3]) {
  out[0] = static_cast<float>(figures.p50 * 1e3);
  out[1] = static_cast<float>(figures.p99 * 1e3);
  out[2] = static_cast<float>(figures.max * 1e3);
}

}  // namespace

LcmDiagnosticsPublisher::LcmDiagnosticsPublisher(const std::string& url, std::string robot,
                                                 std::size_t ticks_per_window)
    : lcm_(open_lcm_url(url, "mc diagnostics")),
      robot_(std::move(robot)),
      ticks_per_window_(std::clamp<std::size_t>(ticks_per_window, 1, kMaxTicksPerWindow)) {
  thread_.start_publishing(windows_, [this](Window& window) { publish(window); });
}

LcmDiagnosticsPublisher::~LcmDiagnosticsPublisher() { finish(); }

void LcmDiagnosticsPublisher::finish() { thread_.stop(); }

void LcmDiagnosticsPublisher::on_cycle(const CycleRecord& record) {
  Window& w = filling_;
  if (record.loop_period_s > 0.0) w.period_s[w.periods++] = record.loop_period_s;
  w.state_age_s[w.ticks] = record.link.state_age_s;
  if (record.link.round_trips != round_trips_seen_) {  // a new measurement (at most one a tick is kept)
    round_trips_seen_ = record.link.round_trips;
    w.round_trip_s[w.round_trips++] = record.link.round_trip_s;
  }
  ++w.ticks;
  w.late_substeps = record.late_substeps;
  w.link = record.link;
  w.timestamp_ns = static_cast<std::int64_t>(std::llround(record.state.time_s * 1e9));
  if (w.ticks < ticks_per_window_) return;
  windows_.try_push(w);  // a full ring drops this second's figures (counted by the ring)
  w.ticks = 0;
  w.periods = 0;
  w.round_trips = 0;
}

void LcmDiagnosticsPublisher::publish(Window& window) {
  mc_diagnostics_lcmt message{};
  message.timestamp = window.timestamp_ns;
  message.ticks = static_cast<std::int32_t>(window.ticks);
  put_ms(window_figures(window.period_s.data(), window.periods), message.loop_period_ms);
  message.late_substeps = static_cast<std::int64_t>(window.late_substeps);
  message.robot = robot_;
  message.link = window.link.present;
  put_ms(window.link.present ? window_figures(window.state_age_s.data(), window.ticks) : WindowFigures{},
         message.state_age_ms);
  put_ms(window_figures(window.round_trip_s.data(), window.round_trips), message.round_trip_ms);
  message.link_losses = static_cast<std::int64_t>(window.link.losses);
  message.states_refused = static_cast<std::int64_t>(window.link.states_refused);
  message.frames_late = static_cast<std::int64_t>(window.link.frames_late);
  lcm_->publish(kChannel, &message);
}

}  // namespace cerebellum
