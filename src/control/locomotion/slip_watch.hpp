// How slippery the ground is, from the feet: the blind MC learns it only from stance feet that
// slide. Each stance gives one observation, the mean horizontal speed (world, on the estimate) of
// its foot over the middle of the stance (the touchdown's and the lift-off's transients left out);
// a foot that slid faster than slip_speed_m_s counts as a slip. The share of slips among the last
// stances (an exponential average) above enter_share marks the ground slippery, under
// leave_share no longer (the hysteresis keeps one fast turn's burst from toggling it).
//
// Measured on the random-command soak, two tuning seeds per floor (docs/benchmarks/locomotion-log.md,
// 2026-12-02): with these defaults the ground read slippery for about 3 % of the stances on the
// model's floor (friction 0.8) and about 40 % on a floor of friction 0.43. (Before the rolling
// was taken out of the speed the caller gives, 4 % and 21 % of single stances slid past 0.1 m/s.)
#pragma once

#include <array>
#include <cstdint>

#include "core/types.hpp"

namespace cerebellum {

struct SlipWatchConfig {
  double window_start_phase = 0.2;  // the part of each stance observed, as shares of the stance
  double window_end_phase = 0.9;
  int min_window_ticks = 4;         // a shorter window (a stance cut short) is no observation
  double slip_speed_m_s = 0.10;
  double share_per_stance = 0.05;   // weight of each new stance in the share (about the last 20)
  double enter_share = 0.16;
  double leave_share = 0.08;
};

struct SlipWatchTelemetry {
  std::uint64_t stances_observed = 0;
  std::uint64_t stances_slipped = 0;
  std::uint64_t slippery_entries = 0;  // times the ground turned slippery
};

class SlipWatch {
 public:
  explicit SlipWatch(const SlipWatchConfig& config = {});

  // once per tick per leg: where the leg is in its stance (in_stance false: in the air) and its
  // foot's horizontal speed over the ground, m/s (read only inside the observed window)
  void observe(std::size_t leg, bool in_stance, double stance_phase, double foot_speed_m_s);

  bool slippery() const { return slippery_; }
  double slip_share() const { return share_; }
  const SlipWatchTelemetry& telemetry() const { return telemetry_; }

 private:
  void end_stance(std::size_t leg);

  SlipWatchConfig config_;
  std::array<double, kNumLegs> speed_sum_m_s_{};
  std::array<int, kNumLegs> window_ticks_{};
  std::array<bool, kNumLegs> was_stance_{};
  double share_ = 0.0;
  bool slippery_ = false;
  SlipWatchTelemetry telemetry_;
};

}  // namespace cerebellum
