#include "control/locomotion/gait.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "control/locomotion/lone_pair.hpp"

namespace cerebellum {
namespace {

constexpr auto kFr = static_cast<std::size_t>(Leg::FR), kFl = static_cast<std::size_t>(Leg::FL);
constexpr auto kRr = static_cast<std::size_t>(Leg::RR), kRl = static_cast<std::size_t>(Leg::RL);

// a start other than the cycle's own must gain this much (m): from a stand, feet symmetric, the
// cycle begins at 0
constexpr double kEntryPreferenceM = 0.01;

GaitPattern make(int id, GaitCycle cycle, std::array<int, 4> offsets, std::array<double, 3> vmin,
                 std::array<double, 3> vmax) {
  GaitPattern p;
  p.id = id;
  p.period_segments = cycle.period_segments;
  p.offsets = offsets;
  p.stance = {cycle.stance_segments, cycle.stance_segments, cycle.stance_segments, cycle.stance_segments};
  p.velocity_min = vmin;
  p.velocity_max = vmax;
  return p;
}

GaitPattern pattern_of(const GaitSpec& gait) {
  GaitPattern p = make(gait.id, gait.cycle, gait.offsets, gait.velocity_min, gait.velocity_max);
  p.adapts_frequency = gait.kind == GaitKind::FrequencyAdapting;
  return p;
}

}  // namespace

std::optional<GaitPattern> gait_pattern(int gait_id) {
  const GaitSpec* gait = find_gait(gait_id);
  if (gait == nullptr) return std::nullopt;
  return pattern_of(*gait);
}

bool legs_swing_together(const GaitPattern& pattern) {
  for (std::size_t leg = 1; leg < kNumLegs; ++leg) {
    if (pattern.offsets[leg] != pattern.offsets[0] || pattern.stance[leg] != pattern.stance[0]) return false;
  }
  return pattern.stance[0] < pattern.period_segments;
}

GaitPattern variable_trot_pattern(double speed_m_s) {
  const int step = std::clamp(static_cast<int>(std::floor(std::abs(speed_m_s) / kVariableTrotSpeedPerCycleMPerS)), 0,
                              static_cast<int>(kVariableTrotCycles.size()) - 1);
  const GaitCycle cycle = kVariableTrotCycles[static_cast<std::size_t>(step)];
  const int half = cycle.period_segments / 2;
  GaitPattern p = pattern_of(*find_gait(kVariableTrotGaitId));
  p.period_segments = cycle.period_segments;
  p.offsets = {0, half, half, 0};
  p.stance.fill(cycle.stance_segments);
  return p;
}

bool steps(const GaitPattern& pattern) {
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
    if (pattern.stance[leg] < pattern.period_segments) return true;
  }
  return false;
}

namespace {

// the leg stands in this segment of the pattern's cycle (any segment, counted on past the period)
bool pattern_stance(const GaitPattern& pattern, std::size_t leg, int segment) {
  const int n = pattern.period_segments;
  return ((segment - pattern.offsets[leg]) % n + n) % n < pattern.stance[leg];
}

// which legs stand in this segment of the pattern's cycle
std::array<bool, kNumLegs> pattern_stances(const GaitPattern& pattern, int segment) {
  std::array<bool, kNumLegs> stance{};
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) stance[leg] = pattern_stance(pattern, leg, segment);
  return stance;
}

bool all_stand(const GaitPattern& pattern, int segment) {
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
    if (!pattern_stance(pattern, leg, segment)) return false;
  }
  return true;
}

// a trot: each diagonal shares its timing, the two diagonals take turns
bool is_trot(const GaitPattern& pattern) {
  return pattern.offsets[kFr] == pattern.offsets[kRl] && pattern.offsets[kFl] == pattern.offsets[kRr] &&
         pattern.offsets[kFr] != pattern.offsets[kFl] && pattern.stance[kFr] == pattern.stance[kRl] &&
         pattern.stance[kFl] == pattern.stance[kRr] && steps(pattern);
}

// the segment of the cycle in which the leg's stance begins
int stance_start_segment(const GaitPattern& pattern, std::size_t leg) {
  return ((pattern.offsets[leg] % pattern.period_segments) + pattern.period_segments) % pattern.period_segments;
}

// distance from the origin to the line through a and b (m); to a itself when they coincide
double distance_to_line_m(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  const double length = (b - a).norm();
  if (length < 1e-9) return a.norm();
  return std::abs(a.x() * b.y() - a.y() * b.x()) / length;
}

// how far the centre lies inside the feet that stand alone first after `segment` (m): the smaller
// lateral distance to the pair's left and right foot; unbounded when no front or rear pair stands
// alone then (a trot's diagonal, a hop's flight)
double first_pair_margin_m(const GaitPattern& pattern, int segment, const std::array<double, kNumLegs>& foot_y) {
  const double unbounded = std::numeric_limits<double>::infinity();
  for (int k = 0; k < pattern.period_segments; ++k) {
    const int s = segment + k;
    if (all_stand(pattern, s)) continue;
    switch (lone_pair(pattern_stances(pattern, s))) {
      case LonePair::Front: return std::min(foot_y[kFl], -foot_y[kFr]);
      case LonePair::Rear: return std::min(foot_y[kRl], -foot_y[kRr]);
      case LonePair::None: return unbounded;
    }
    return unbounded;
  }
  return unbounded;
}

}  // namespace

int entry_segment(const GaitPattern& pattern, const std::array<double, kNumLegs>& foot_y_from_com_m) {
  int best = 0;
  double best_margin = first_pair_margin_m(pattern, 0, foot_y_from_com_m);
  for (int s = 1; s < pattern.period_segments; ++s) {
    // the first segment of a run in which every foot stands
    if (!all_stand(pattern, s) || all_stand(pattern, s - 1)) continue;
    const double margin = first_pair_margin_m(pattern, s, foot_y_from_com_m);
    if (margin > best_margin + kEntryPreferenceM) {
      best = s;
      best_margin = margin;
    }
  }
  return best;
}

int sideways_entry_segment(const GaitPattern& pattern, double lateral_velocity_m_s, double min_speed_m_s) {
  if (std::abs(lateral_velocity_m_s) < min_speed_m_s || !is_trot(pattern)) return 0;
  // the rear foot on the side the body moves toward (body y: left is +)
  return stance_start_segment(pattern, lateral_velocity_m_s > 0.0 ? kRl : kRr);
}

int diagonal_entry_segment(const GaitPattern& pattern,
                           const std::array<Eigen::Vector2d, kNumLegs>& foot_xy_from_com_m) {
  if (!is_trot(pattern)) return 0;
  const double fr_rl = distance_to_line_m(foot_xy_from_com_m[kFr], foot_xy_from_com_m[kRl]);
  const double fl_rr = distance_to_line_m(foot_xy_from_com_m[kFl], foot_xy_from_com_m[kRr]);
  if (fl_rr + kEntryPreferenceM < fr_rl) return stance_start_segment(pattern, kFl);
  if (fr_rl + kEntryPreferenceM < fl_rr) return stance_start_segment(pattern, kFr);
  return 0;
}

bool stands_on_lone_pairs(const GaitPattern& pattern) {
  for (int segment = 0; segment < pattern.period_segments; ++segment) {
    if (lone_pair(pattern_stances(pattern, segment)) != LonePair::None) return true;
  }
  return false;
}

GaitPattern stand_bridge_pattern(int segments) {
  const int period = std::max(segments, 1);
  return make(kStandGaitId, {period, period}, {0, 0, 0, 0}, {0, 0, 0}, {0, 0, 0});
}

GaitScheduler::GaitScheduler(double segment_s) : segment_s_(segment_s), pattern_(*gait_pattern(kStandGaitId)) {}

double GaitScheduler::cycle_phase() const {
  if (sequence_ != nullptr) return 0.0;
  return (segment_ + time_in_segment_s_ / segment_s_) / pattern_.period_segments;
}

void GaitScheduler::play(std::shared_ptr<const ContactSequence> sequence) {
  sequence_ = std::move(sequence);
  segment_ = 0;
  time_in_segment_s_ = 0.0;
}

void GaitScheduler::set_pattern(const GaitPattern& pattern) {
  const double phase = cycle_phase();
  sequence_.reset();
  pattern_ = pattern;
  const double position = phase * pattern_.period_segments;
  segment_ = std::clamp(static_cast<int>(std::floor(position)), 0, pattern_.period_segments - 1);
  time_in_segment_s_ = (position - segment_) * segment_s_;
}

void GaitScheduler::restart(const GaitPattern& pattern, int segment) {
  sequence_.reset();
  pattern_ = pattern;
  segment_ = std::clamp(segment, 0, pattern_.period_segments - 1);
  time_in_segment_s_ = 0.0;
}

void GaitScheduler::advance(double dt_s) {
  time_in_segment_s_ += dt_s;
  while (time_in_segment_s_ >= segment_s_ - 1e-12) {
    time_in_segment_s_ -= segment_s_;
    if (sequence_ != nullptr) {
      segment_ = std::min(segment_ + 1, sequence_->segments());  // stays at the end: standing
    } else {
      segment_ = (segment_ + 1) % pattern_.period_segments;
    }
  }
  time_in_segment_s_ = std::max(0.0, time_in_segment_s_);
}

bool GaitScheduler::in_stance(std::size_t leg, int segment) const {
  if (sequence_ != nullptr) return sequence_->in_stance(leg, segment);
  return pattern_stance(pattern_, leg, segment);
}

LegPhase GaitScheduler::leg_phase(std::size_t leg) const {
  if (sequence_ != nullptr) {
    LegPhase phase;
    if (segment_ >= sequence_->segments()) return phase;  // standing after the end
    const ContactSequence::Run run = sequence_->run(leg, segment_);
    const double share = (segment_ - run.first + time_in_segment_s_ / segment_s_) / run.length;
    // the duration of the other kind of run next to it, for footholds and the estimator
    const int next = run.first + run.length;
    const int other = next < sequence_->segments() ? sequence_->run(leg, next).length : run.length;
    phase.stance = sequence_->in_stance(leg, segment_);
    if (phase.stance) {
      phase.stance_phase = share;
      phase.stance_duration_s = run.length * segment_s_;
      phase.swing_duration_s = other * segment_s_;
    } else {
      phase.swing_phase = share;
      phase.swing_duration_s = run.length * segment_s_;
      phase.stance_duration_s = other * segment_s_;
    }
    return phase;
  }
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
