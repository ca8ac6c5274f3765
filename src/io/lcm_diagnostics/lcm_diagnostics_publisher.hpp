// The MC's own figures, once a second, for `cerebellum status`: the loop's period (p50 / p99 / max
// of the wall time between ticks, while paced) and the real robot's link (the state's age when a
// tick read it, the round trip where the link shows it, losses, refused states, late frames), on
// channel mc_diagnostics. An observer: it copies each tick's figures from the cycle record into a
// window; the window goes to its thread, which computes the percentiles and publishes.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>

#include "core/robot_readings.hpp"
#include "core/spsc_ring.hpp"
#include "cycle/cycle_observer.hpp"
#include "io/common/adapter_thread.hpp"

namespace lcm {
class LCM;
}

namespace cerebellum {

class LcmDiagnosticsPublisher final : public CycleObserver {
 public:
  // url: where (the high-level response url); robot: robot.kind's name; ticks_per_window: a
  // second's ticks. Throws std::runtime_error naming a url LCM cannot open
  LcmDiagnosticsPublisher(const std::string& url, std::string robot, std::size_t ticks_per_window);
  ~LcmDiagnosticsPublisher() override;
  LcmDiagnosticsPublisher(const LcmDiagnosticsPublisher&) = delete;
  LcmDiagnosticsPublisher& operator=(const LcmDiagnosticsPublisher&) = delete;

  void on_cycle(const CycleRecord& record) override;
  // stops the thread (publishing a window that is already queued)
  void finish();

  static constexpr std::size_t kMaxTicksPerWindow = 1024;

 private:
  struct Window {
    std::int64_t timestamp_ns = 0;
    std::size_t ticks = 0;
    std::size_t periods = 0;  // ticks with a loop period (paced, not the first)
    std::array<double, kMaxTicksPerWindow> period_s{};
    std::array<double, kMaxTicksPerWindow> state_age_s{};
    std::size_t round_trips = 0;  // new round-trip measurements in the window
    std::array<double, kMaxTicksPerWindow> round_trip_s{};
    std::uint64_t late_substeps = 0;
    RobotLinkReport link;
  };

  void publish(Window& window);

  std::unique_ptr<lcm::LCM> lcm_;
  std::string robot_;
  std::size_t ticks_per_window_;
  // loop thread only
  Window filling_;
  std::uint64_t round_trips_seen_ = 0;
  // loop -> publisher thread: a window a second, copied (no allocation in the loop)
  SpscRing<Window, 4> windows_;
  AdapterThread thread_;
};

}  // namespace cerebellum
