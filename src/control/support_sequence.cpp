#include "control/support_sequence.hpp"

#include <algorithm>

#include "control/stand_up_controller.hpp"
#include "control/joint_ramp.hpp"

namespace cerebellum {

SupportSequence::SupportSequence(const SupportSequenceConfig& config) : config_(config) {}

void SupportSequence::reset() {
  leg_ = kNoLeg;
  requested_ = kNoLeg;
  phase_ = 0.0;
}

void SupportSequence::request(int leg) { requested_ = leg; }

void SupportSequence::advance(double dt_s) {
  // switch legs only with all four feet down
  if (leg_ != requested_ && phase_ <= 0.0) leg_ = requested_;
  if (leg_ == kNoLeg) {
    phase_ = 0.0;
    return;
  }
  const double goal = leg_ == requested_ ? 3.0 : 0.0;
  // each segment runs at its own rate
  const double durations[3] = {config_.shift_duration_s, config_.unload_duration_s, config_.lift_duration_s};
  double remaining_s = dt_s;
  while (remaining_s > 0.0 && phase_ != goal) {
    const bool rising = goal > phase_;
    const int segment = std::clamp(static_cast<int>(rising ? phase_ : phase_ - 1e-12), 0, 2);
    const double rate = 1.0 / std::max(durations[segment], 1e-6);
    const double boundary = rising ? segment + 1.0 : static_cast<double>(segment);
    const double needed_s = std::abs(boundary - phase_) / rate;
    if (needed_s >= remaining_s) {
      phase_ += (rising ? 1.0 : -1.0) * rate * remaining_s;
      remaining_s = 0.0;
    } else {
      phase_ = boundary;
      remaining_s -= needed_s;
    }
  }
  // back on four feet: the next leg (or none) takes over
  if (phase_ <= 0.0) {
    phase_ = 0.0;
    leg_ = requested_;
  }
}

double SupportSequence::shift() const { return leg_ == kNoLeg ? 0.0 : smooth_step(phase_); }
double SupportSequence::load() const { return leg_ == kNoLeg ? 1.0 : 1.0 - smooth_step(phase_ - 1.0); }
double SupportSequence::lift() const { return leg_ == kNoLeg ? 0.0 : smooth_step(phase_ - 2.0); }

double SupportSequence::progress() const {
  if (settled()) return 1.0;
  // lifting runs the phase up to 3; putting down (also before lifting another leg) runs it down
  return leg_ == requested_ ? phase_ / 3.0 : 1.0 - phase_ / 3.0;
}

bool SupportSequence::settled() const {
  if (requested_ == kNoLeg) return leg_ == kNoLeg;
  return leg_ == requested_ && phase_ >= 3.0;
}

}  // namespace cerebellum
