#include "io/lcm_highlevel/response_schedule.hpp"

#include <algorithm>
#include <cmath>

namespace cerebellum {
namespace {

std::uint64_t ticks_per(double period_s, double loop_period_s) {
  return static_cast<std::uint64_t>(std::max(1L, std::lround(period_s / loop_period_s)));
}

}  // namespace

ResponseSchedule::ResponseSchedule(double loop_period_s)
    : feedback_every_ticks_(ticks_per(kFeedbackPeriodS, loop_period_s)),
      temperature_every_ticks_(ticks_per(kTemperaturePeriodS, loop_period_s)) {}

PublishDue ResponseSchedule::on_tick(std::uint64_t tick, const HighLevelStatus& status) {
  PublishDue due;
  due.odometry = tick % feedback_every_ticks_ == 0;
  due.temperature = tick % temperature_every_ticks_ == 0;
  due.response = due.odometry;
  if (seen_) {
    // events: a new switch status, or an uninterruptible motion reaching "finished"
    const bool switched = status.switch_status != last_switch_;
    const bool finished = last_bar_ < kFinishedPercent && status.order_process_bar >= kFinishedPercent;
    due.response = due.response || switched || finished;
  }
  seen_ = true;
  last_switch_ = status.switch_status;
  last_bar_ = status.order_process_bar;
  return due;
}

}  // namespace cerebellum
