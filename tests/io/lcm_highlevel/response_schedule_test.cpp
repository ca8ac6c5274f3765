#include "io/lcm_highlevel/response_schedule.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace cerebellum {
namespace {

HighLevelStatus status_with(int bar, SwitchStatus switch_status = SwitchStatus::Done) {
  HighLevelStatus status;
  status.order_process_bar = bar;
  status.switch_status = switch_status;
  return status;
}

struct Counts {
  int responses = 0;
  int odometry = 0;
  int temperatures = 0;
};

Counts run_steady(ResponseSchedule& schedule, std::uint64_t first_tick, std::uint64_t ticks) {
  Counts counts;
  for (std::uint64_t t = first_tick; t < first_tick + ticks; ++t) {
    const PublishDue due = schedule.on_tick(t, status_with(100));
    counts.responses += due.response;
    counts.odometry += due.odometry;
    counts.temperatures += due.temperature;
  }
  return counts;
}

TEST(ResponseSchedule, FiftyHertzFeedbackAndOneHertzTemperatureAt500Hz) {
  ResponseSchedule schedule(0.002);
  EXPECT_EQ(schedule.feedback_every_ticks(), 10u);
  EXPECT_EQ(schedule.temperature_every_ticks(), 500u);
  const Counts second = run_steady(schedule, 0, 500);
  EXPECT_EQ(second.responses, 50);
  EXPECT_EQ(second.odometry, 50);
  EXPECT_EQ(second.temperatures, 1);
  const Counts three_more = run_steady(schedule, 500, 1500);
  EXPECT_EQ(three_more.responses, 150);
  EXPECT_EQ(three_more.temperatures, 3);
}

TEST(ResponseSchedule, RatesFollowTheLoopPeriod) {
  ResponseSchedule fast(0.001);
  EXPECT_EQ(fast.feedback_every_ticks(), 20u);
  EXPECT_EQ(run_steady(fast, 0, 1000).responses, 50);
  ResponseSchedule slow(0.01);
  EXPECT_EQ(slow.feedback_every_ticks(), 2u);
  EXPECT_EQ(run_steady(slow, 0, 100).responses, 50);
  EXPECT_EQ(slow.temperature_every_ticks(), 100u);
}

TEST(ResponseSchedule, SwitchStatusChangeIsPublishedAtOnceAndOnlyOnce) {
  ResponseSchedule schedule(0.002);
  schedule.on_tick(0, status_with(100));
  EXPECT_FALSE(schedule.on_tick(1, status_with(100)).response);
  EXPECT_TRUE(schedule.on_tick(2, status_with(100, SwitchStatus::BanTransition)).response);
  EXPECT_FALSE(schedule.on_tick(3, status_with(100, SwitchStatus::BanTransition)).response);
  EXPECT_TRUE(schedule.on_tick(4, status_with(100, SwitchStatus::Done)).response);
  EXPECT_FALSE(schedule.on_tick(5, status_with(100)).response);
  // an event on a scheduled tick is one response
  const PublishDue due = schedule.on_tick(10, status_with(100, SwitchStatus::Transitioning));
  EXPECT_TRUE(due.response);
  EXPECT_TRUE(due.odometry);
}

TEST(ResponseSchedule, ProgressReaching95IsPublishedOncePerMotion) {
  ResponseSchedule schedule(0.002);
  std::vector<std::uint64_t> extra;
  const std::vector<int> bars{0, 40, 94, 95, 96, 100, 100, 0, 50, 100, 100};
  for (std::uint64_t t = 0; t < bars.size(); ++t) {
    // never on the 10-tick schedule
    const std::uint64_t tick = 10 * t + 1;
    if (schedule.on_tick(tick, status_with(bars[t])).response) extra.push_back(t);
  }
  EXPECT_EQ(extra, (std::vector<std::uint64_t>{3, 9}));
}

TEST(ResponseSchedule, FirstTickIsNoEvent) {
  ResponseSchedule schedule(0.002);
  const PublishDue due = schedule.on_tick(7, status_with(100, SwitchStatus::BanTransition));
  EXPECT_FALSE(due.any());
}

}  // namespace
}  // namespace cerebellum
