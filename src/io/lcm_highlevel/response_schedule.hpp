// When the high-level interface publishes, decided per control tick from the machine's status:
// the response every 20 ms (every 10th 2 ms tick), immediately when switch_status changes and once
// when order_process_bar first reaches 95; the odometry every 20 ms; motor temperatures every 1 s.
#pragma once

#include <cstdint>

#include "core/high_level_command.hpp"

namespace cerebellum {

struct PublishDue {
  bool response = false;
  bool odometry = false;
  bool temperature = false;
  bool any() const { return response || odometry || temperature; }
};

class ResponseSchedule {
 public:
  static constexpr double kFeedbackPeriodS = 0.02;
  static constexpr double kTemperaturePeriodS = 1.0;
  static constexpr int kFinishedPercent = 95;

  explicit ResponseSchedule(double loop_period_s);

  // tick: the loop's tick counter (0 on the first tick)
  PublishDue on_tick(std::uint64_t tick, const HighLevelStatus& status);

  std::uint64_t feedback_every_ticks() const { return feedback_every_ticks_; }
  std::uint64_t temperature_every_ticks() const { return temperature_every_ticks_; }

 private:
  std::uint64_t feedback_every_ticks_;
  std::uint64_t temperature_every_ticks_;
  bool seen_ = false;
  SwitchStatus last_switch_ = SwitchStatus::Done;
  int last_bar_ = 0;
};

}  // namespace cerebellum
