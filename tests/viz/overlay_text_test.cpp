// The viewer's and the recorder's status text.
#include "viz/overlay_text.hpp"

#include <gtest/gtest.h>

#include <algorithm>

namespace cerebellum {
namespace {

std::size_t lines(const std::string& text) { return std::count(text.begin(), text.end(), '\n') + 1; }

TEST(OverlayText, NamesTheInterfaceModesAndSaysWhenAModeIsUnknown) {
  EXPECT_EQ(mode_name(0), "off");
  EXPECT_EQ(mode_name(7), "pure damper");
  EXPECT_EQ(mode_name(11), "locomotion");
  EXPECT_EQ(mode_name(12), "recovery stand");
  EXPECT_EQ(mode_name(21), "pose control");
  EXPECT_EQ(mode_name(99), "mode 99");
  EXPECT_STREQ(switch_status_name(SwitchStatus::Transitioning), "transitioning");
  EXPECT_STREQ(switch_status_name(SwitchStatus::BanTransition), "ban transition");
}

TEST(OverlayText, ShowsStatusEstimateAndTruthRowByRowThenTheRunAndTheKeyboardsCommand) {
  SimSnapshot snapshot;
  snapshot.time_s = 12.346;
  snapshot.status.mode = 11;
  snapshot.status.gait_id = 27;
  snapshot.status.switch_status = SwitchStatus::Done;
  snapshot.commanded_velocity = {0.3, 0.0, 0.2};
  snapshot.estimated_velocity_body = {0.31, -0.05, 0.2};
  snapshot.true_velocity_body = {0.29, -0.04, 0.19};
  snapshot.estimated_height_m = 0.251;
  snapshot.true_height_m = 0.249;
  snapshot.battery_soc_percent = 87.34;
  snapshot.battery_v = 24.61;
  snapshot.hottest_motor = 5;
  snapshot.hottest_motor_c = 41.2;
  snapshot.faulty_motors = (1u << 2) | (1u << 11);

  const OverlayText text = status_overlay(snapshot, "paused");
  ASSERT_EQ(lines(text.titles), lines(text.values));
  EXPECT_EQ(text.titles, "12.35 s\ncommanded\nestimated\ntruth\nrobot\nrun");
  EXPECT_EQ(text.values,
            "mode 11 locomotion, gait 27, done\nvx +0.30  vy +0.00 m/s  wz +0.20 rad/s\n"
            "vx +0.31  vy -0.05 m/s  wz +0.20 rad/s  height 0.251 m\n"
            "vx +0.29  vy -0.04 m/s  wz +0.19 rad/s  height 0.249 m\n"
            "battery 87.3 %  24.6 V  hottest motor 41 C (FL knee)  faulty motors: 2 11\npaused");

  const OverlayText without_run_state = status_overlay(snapshot, "");
  EXPECT_EQ(lines(without_run_state.titles), lines(text.titles) - 1);
  EXPECT_EQ(lines(without_run_state.values), lines(text.values) - 1);

  const OverlayText with_keys = status_overlay(snapshot, "paused", "sent mode 12 (recovery stand) gait 0");
  ASSERT_EQ(lines(with_keys.titles), lines(with_keys.values));
  EXPECT_EQ(with_keys.titles, text.titles + "\nkeys");
  EXPECT_EQ(with_keys.values, text.values + "\nsent mode 12 (recovery stand) gait 0");
}

}  // namespace
}  // namespace cerebellum
