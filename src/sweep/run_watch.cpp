#include "sweep/run_watch.hpp"

#include <algorithm>
#include <cmath>

#include "modes/jump_mode.hpp"
#include "safety/command_finite.hpp"
#include "sweep/random_soak.hpp"

namespace cerebellum {

namespace {

constexpr double kRadToDeg = 180.0 / 3.14159265358979323846;

}  // namespace

bool damped_or_off(const JointCommand& c) {
  return std::all_of(c.kp.begin(), c.kp.end(), [](double kp) { return kp == 0.0; }) &&
         std::all_of(c.tau_ff.begin(), c.tau_ff.end(), [](double tau) { return tau == 0.0; });
}

void RunWatch::fault_until(double end_s) { last_fault_end_s_ = std::max(last_fault_end_s_, end_s); }

void RunWatch::observe(const CycleRecord& record, const GroundTruth& truth, double now_s) {
  ++result_.ticks;
  if (!command_is_finite(record.command)) ++result_.non_finite_commands;
  if (record.health.protecting() && !was_protecting_) ++result_.protections;
  was_protecting_ = record.health.protecting();
  const double tilt = tilt_rad(truth);
  result_.max_tilt_deg = std::max(result_.max_tilt_deg, tilt * kRadToDeg);
  // a flip's own turn is not a fall; one that ends tipped over is, when it ends
  const HighLevelStatus& status = record.high_level.status;
  const bool flipping = status.mode == static_cast<int>(ModeId::Jump3d) &&
                        (status.gait_id == kBackFlipGaitId || status.gait_id == kFrontFlipGaitId) &&
                        status.order_process_bar < 100;
  const bool up = tilt < kFallTiltRad || flipping;
  if (up_ && !up) {
    ++result_.falls;
    fall_times_s_.push_back(now_s);
    if (result_.first_fall_s < 0) result_.first_fall_s = now_s;
    if (now_s > last_fault_end_s_ + kFallExplainedWithinS) ++result_.falls_no_fault_near;
    safe_deadline_s_ = now_s + kSafeAfterFallS;
  }
  up_ = up;
  if (awaiting_safety()) {
    if (damped_or_off(record.command) || up) {
      safe_deadline_s_ = -1.0;
    } else if (now_s > safe_deadline_s_) {
      ++result_.falls_not_safe;
      safe_deadline_s_ = -1.0;
    }
  }
}

void RunWatch::finish() {
  if (awaiting_safety()) ++result_.falls_not_safe;
  safe_deadline_s_ = -1.0;
}

}  // namespace cerebellum
