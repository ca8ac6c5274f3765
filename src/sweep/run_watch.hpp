// The per-tick judgement of a run: falls (and whether a fault explains them and the motors were
// made safe after), protections, non-finite commands, the largest tilt.
#pragma once

#include <vector>

#include "backend/simulation.hpp"
#include "cycle/cycle_record.hpp"
#include "sweep/run_result.hpp"

namespace cerebellum {

// a fall within this long of a fault's end is put down to the fault
inline constexpr double kFallExplainedWithinS = 5.0;
// after a fall the motors must be damped or off (or the robot upright again) within this long
inline constexpr double kSafeAfterFallS = 3.0;

// every joint without stiffness or feed-forward torque: damping, or the motors off
bool damped_or_off(const JointCommand& command);

class RunWatch {
 public:
  explicit RunWatch(RunResult& result) : result_(result) {}

  // a fault is active until end_s (a very large end_s: until cleared)
  void fault_until(double end_s);
  void observe(const CycleRecord& record, const GroundTruth& truth, double now_s);
  // a fall whose safety is still being watched
  bool awaiting_safety() const { return safe_deadline_s_ >= 0.0; }
  // when the fall of that number (0 first) happened
  double fall_s(int fall) const { return fall_times_s_.at(static_cast<std::size_t>(fall)); }
  // at the run's end: a fall still awaiting safety is judged not safe
  void finish();

 private:
  RunResult& result_;
  bool up_ = true;
  bool was_protecting_ = false;
  double last_fault_end_s_ = -1e9;
  double safe_deadline_s_ = -1.0;
  std::vector<double> fall_times_s_;
};

}  // namespace cerebellum
