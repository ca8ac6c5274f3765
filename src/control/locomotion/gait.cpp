#include "control/locomotion/gait.hpp"

#include <algorithm>
#include <cmath>

namespace cerebellum {
namespace {

GaitPattern make(int id, int period, std::array<int, 4> offsets, int stance, std::array<double, 3> vmin,
                 std::array<double, 3> vmax) {
  GaitPattern p;
  p.id = id;
  p.period_segments = period;
  p.offsets = offsets;
  p.stance = {stance, stance, stance, stance};
  p.velocity_min = vmin;
  p.velocity_max = vmax;
  return p;
}

// the variable-frequency trot's steps: (period, stance) as speed grows
constexpr std::array<std::array<int, 2>, 8> kVariableTrotSteps{
    {{24, 16}, {22, 14}, {20, 12}, {18, 11}, {16, 10}, {14, 8}, {12, 6}, {10, 5}}};

}  // namespace

std::optional<GaitPattern> gait_pattern(int gait_id) {
  switch (gait_id) {
    case 1:
    case 31: return make(gait_id, 10, {0, 0, 0, 0}, 10, {0, 0, 0}, {0, 0, 0});
    case 2: return make(2, 10, {0, 0, 0, 0}, 4, {-0.10, -0.15, -0.50}, {0.20, 0.15, 0.50});
    case 3: return make(3, 12, {0, 6, 6, 0}, 6, {-1.2, -0.4, -2.25}, {1.2, 0.4, 2.25});
    case 4: return make(4, 12, {0, 6, 6, 0}, 6, {-0.65, -0.4, -0.80}, {0.65, 0.4, 0.80});
    case 7: return make(7, 12, {6, 6, 0, 0}, 8, {-0.3, -0.3, -1.5}, {0.3, 0.3, 1.5});
    case 10: return make(10, 10, {0, 5, 5, 0}, 4, {-1.2, -0.55, -2.5}, {1.6, 0.55, 2.5});
    case 26: return variable_trot_pattern(0.0);
    case 27: return make(27, 20, {0, 10, 10, 0}, 12, {-0.60, -0.2, -1.30}, {0.60, 0.2, 1.30});
    default: return std::nullopt;
  }
}

bool legs_swing_together(const GaitPattern& pattern) {
  for (std::size_t leg = 1; leg < kNumLegs; ++leg) {
    if (pattern.offsets[leg] != pattern.offsets[0] || pattern.stance[leg] != pattern.stance[0]) return false;
  }
  return pattern.stance[0] < pattern.period_segments;
}

GaitPattern variable_trot_pattern(double speed_m_s) {
  // one step per 0.2 m/s of speed
  const int step = std::clamp(static_cast<int>(std::floor(std::abs(speed_m_s) / 0.2)), 0,
                              static_cast<int>(kVariableTrotSteps.size()) - 1);
  const auto [period, stance] = kVariableTrotSteps[static_cast<std::size_t>(step)];
  GaitPattern p = make(26, period, {0, period / 2, period / 2, 0}, stance, {-1.2, -0.6, -2.5}, {1.6, 0.6, 2.5});
  p.adapts_frequency = true;
  return p;
}

bool steps(const GaitPattern& pattern) {
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
    if (pattern.stance[leg] < pattern.period_segments) return true;
  }
  return false;
}

GaitPattern stand_bridge_pattern(int segments) {
  const int period = std::max(segments, 1);
  return make(1, period, {0, 0, 0, 0}, period, {0, 0, 0}, {0, 0, 0});
}

GaitScheduler::GaitScheduler(double segment_s) : segment_s_(segment_s), pattern_(*gait_pattern(1)) {}

double GaitScheduler::cycle_phase() const {
  return (segment_ + time_in_segment_s_ / segment_s_) / pattern_.period_segments;
}

void GaitScheduler::set_pattern(const GaitPattern& pattern) {
  const double phase = cycle_phase();
  pattern_ = pattern;
  const double position = phase * pattern_.period_segments;
  segment_ = std::clamp(static_cast<int>(std::floor(position)), 0, pattern_.period_segments - 1);
  time_in_segment_s_ = (position - segment_) * segment_s_;
}

void GaitScheduler::advance(double dt_s) {
  time_in_segment_s_ += dt_s;
  while (time_in_segment_s_ >= segment_s_ - 1e-12) {
    time_in_segment_s_ -= segment_s_;
    segment_ = (segment_ + 1) % pattern_.period_segments;
  }
  time_in_segment_s_ = std::max(0.0, time_in_segment_s_);
}

bool GaitScheduler::in_stance(std::size_t leg, int segment) const {
  const int n = pattern_.period_segments;
  const int since_start = ((segment - pattern_.offsets[leg]) % n + n) % n;
  return since_start < pattern_.stance[leg];
}

LegPhase GaitScheduler::leg_phase(std::size_t leg) const {
  const int n = pattern_.period_segments;
  const double position = segment_ + time_in_segment_s_ / segment_s_;
  double since_start = std::fmod(position - pattern_.offsets[leg] + n, static_cast<double>(n));
  LegPhase phase;
  const int stance = pattern_.stance[leg];
  phase.stance_duration_s = stance * segment_s_;
  phase.swing_duration_s = (n - stance) * segment_s_;
  if (since_start < stance) {
    phase.stance = true;
    phase.stance_phase = since_start / stance;
  } else {
    phase.stance = false;
    phase.swing_phase = (since_start - stance) / (n - stance);
  }
  return phase;
}

}  // namespace cerebellum
