// Gaits of mode 11 as contact schedules: a cycle of MPC segments (30 ms each) in which each leg
// has a stance window starting at its offset; the rest of the cycle is swing.
#pragma once

#include <array>
#include <memory>
#include <optional>

#include <Eigen/Core>

#include "control/locomotion/contact_sequence.hpp"
#include "control/locomotion/gait_table.hpp"
#include "core/joint_layout.hpp"

namespace cerebellum {

struct GaitPattern {
  int id = 0;
  int period_segments = 10;
  std::array<int, kNumLegs> offsets{};  // segment in which stance starts (FR, FL, RR, RL)
  std::array<int, kNumLegs> stance{};   // stance length in segments
  // velocity limits (vx, vy, yaw rate), clamped, not rejected
  std::array<double, 3> velocity_min{};
  std::array<double, 3> velocity_max{};
  bool adapts_frequency = false;  // GaitKind::FrequencyAdapting: the period follows the speed
};

// the pattern of a gait id of the gait table, or nothing for an unknown id
std::optional<GaitPattern> gait_pattern(int gait_id);

// true for a hop (pronk): every leg lifts and lands together
bool legs_swing_together(const GaitPattern& pattern);

// the variable-frequency trot's pattern for a commanded speed (m/s)
GaitPattern variable_trot_pattern(double speed_m_s);

// true for a pattern in which some leg swings (false for a stand)
bool steps(const GaitPattern& pattern);

// all feet on the ground for a few segments: the bridge from one stepping gait to another
GaitPattern stand_bridge_pattern(int segments);

// true for a pattern in which, at some segment, the front or the rear pair stands with no other
// foot down (the bound): such a gait pitches the trunk from pair to pair
bool stands_on_lone_pairs(const GaitPattern& pattern);

// the segment at which a pattern's cycle begins, from a stand or a bridge, given each foot's
// lateral position from the centre of mass (body y, m). A gait in which the front or the rear pair
// stands alone (the bound) begins at the all-stance segment after which the pair that stands alone
// first straddles the centre widest; the other pair swings first and lands under its hips. Feet a
// trot leaves behind lie up to 10 cm inward (a sideways or turning walk carries the body over its
// stance feet), and a bound whose first pair stood on one of them rolled over it. Otherwise 0.
int entry_segment(const GaitPattern& pattern, const std::array<double, kNumLegs>& foot_y_from_com_m);

// the segment at which a trot begins from a stand while the body moves sideways at
// lateral_velocity_m_s (body y): the diagonal whose rear foot lies on the side the body moves
// toward stands first, so the front foot on that side steps out first, and a push from either side
// meets the mirror image of the same steps (the trot used to begin with the same diagonal whichever
// way the body moved; gait 1 then caught 25 N s from one side and fell from the other). Below
// min_speed_m_s, or for a gait that is no trot, the cycle begins at 0
int sideways_entry_segment(const GaitPattern& pattern, double lateral_velocity_m_s, double min_speed_m_s);

// the segment at which a trot begins after the bridge out of a bound, given each foot's position
// from the centre of mass (body x, y; m): the diagonal whose support line passes more than 1 cm
// nearer the centre stands first. The bound leaves its feet wherever its last leaps put them, and
// the trunk pitched; a slow trot that began on its own first diagonal, whose line passed 10 cm
// beside the centre, rolled over it (benchmarks.md). For a gait that is no trot, or when neither
// diagonal is nearer, 0
int diagonal_entry_segment(const GaitPattern& pattern, const std::array<Eigen::Vector2d, kNumLegs>& foot_xy_from_com_m);

// where each leg is in the cycle at one instant
struct LegPhase {
  bool stance = true;
  double stance_phase = 0.0;  // 0..1 through the stance window (valid in stance)
  double swing_phase = 0.0;   // 0..1 through the swing window (valid in swing)
  double stance_duration_s = 0.0;
  double swing_duration_s = 0.0;
};

// runs a pattern in time (or a contact sequence once): phase per leg and the contact table of the
// MPC horizon
class GaitScheduler {
 public:
  explicit GaitScheduler(double segment_s = kGaitSegmentS);

  // switch pattern, keeping the cycle phase (fraction of the cycle) continuous; ends a sequence
  void set_pattern(const GaitPattern& pattern);
  // switch pattern and begin its cycle at `segment` (a stand's phase means nothing to a gait)
  void restart(const GaitPattern& pattern, int segment = 0);
  const GaitPattern& pattern() const { return pattern_; }
  // play a sequence from its first segment; the pattern waits until set_pattern() is called again
  void play(std::shared_ptr<const ContactSequence> sequence);
  // a sequence is being played (finished or not)
  bool playing() const { return sequence_ != nullptr; }
  // the played sequence has reached its end (every leg stands from here on)
  bool sequence_finished() const { return sequence_ != nullptr && segment_ >= sequence_->segments(); }

  void advance(double dt_s);
  LegPhase leg_phase(std::size_t leg) const;
  // contact of each leg at horizon step k (k = 0 is the current segment)
  template <std::size_t Horizon>
  std::array<std::array<bool, kNumLegs>, Horizon> horizon_contacts() const {
    std::array<std::array<bool, kNumLegs>, Horizon> table{};
    for (std::size_t k = 0; k < Horizon; ++k) {
      for (std::size_t leg = 0; leg < kNumLegs; ++leg) table[k][leg] = in_stance(leg, segment_ + static_cast<int>(k));
    }
    return table;
  }
  double segment_s() const { return segment_s_; }
  // fraction of the cycle, 0..1
  double cycle_phase() const;

 private:
  bool in_stance(std::size_t leg, int segment) const;

  double segment_s_;
  GaitPattern pattern_;
  std::shared_ptr<const ContactSequence> sequence_;
  int segment_ = 0;  // current segment in the cycle (in the sequence while one is played)
  double time_in_segment_s_ = 0.0;
};

}  // namespace cerebellum
