#include "loop/control_loop.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <thread>

namespace cerebellum {

ControlLoop::ControlLoop(RobotBackend& backend, StateEstimator& estimator, MotionController& controller,
                         const GuardLimits& guard_limits, double period_s, double substep_s)
    : backend_(backend),
      estimator_(estimator),
      controller_(controller),
      guard_limits_(guard_limits),
      health_(guard_limits.health),
      period_s_(period_s),
      substeps_(0) {
  if (!(period_s > 0.0)) throw std::invalid_argument("control period must be > 0 s");
  if (!(substep_s > 0.0) || substep_s > period_s) throw std::invalid_argument("substep must be in (0, period]");
  const double ratio = period_s / substep_s;
  substeps_ = static_cast<int>(std::lround(ratio));
  if (std::abs(ratio - substeps_) > 1e-9) throw std::invalid_argument("substep must divide the control period");
  observers_.reserve(8);
  substep_participants_.reserve(4);
}

void ControlLoop::add_observer(CycleObserver& observer) { observers_.push_back(&observer); }

void ControlLoop::add_substep_participant(SubstepParticipant& participant) {
  substep_participants_.push_back(&participant);
}

const CycleRecord& ControlLoop::tick() {
  // the loop's own timing, while paced by the wall clock
  if (pace_speed_ > 0.0) {
    const auto now = std::chrono::steady_clock::now();
    record_.loop_period_s = last_tick_wall_ == std::chrono::steady_clock::time_point{}
                                ? 0.0
                                : std::chrono::duration<double>(now - last_tick_wall_).count();
    last_tick_wall_ = now;
  } else {
    record_.loop_period_s = 0.0;
    last_tick_wall_ = {};
  }
  record_.late_substeps = late_substeps_;
  // read
  const SensorFrame frame = backend_.read();
  record_.link = backend_.link_report();
  // estimate, with the contacts the control stage planned last tick
  estimator_.update(frame, record_.contact_plan, record_.state);
  // the robot's health: the controller learns the protection, the guard enforces it
  record_.health = health_.update(record_.state);
  controller_.observe_health(record_.health);
  // decide and control: an invalid state gets no command (and no new plan) from the controller
  if (record_.state.valid) {
    controller_.compute(record_.state, record_.command);
    record_.contact_plan = controller_.contact_plan();
  }
  controller_.report(record_.high_level);
  // guard, always last
  record_.safety = guard_command(record_.state, record_.command, guard_limits_, record_.health.protection);
  // write, then the robot runs one period
  backend_.write(record_.command);
  for (CycleObserver* observer : observers_) observer->on_cycle(record_);
  run_substeps();
  ++record_.tick;
  return record_;
}

void ControlLoop::run_substeps() {
  const double substep_s = period_s_ / substeps_;
  record_.substep_safety = SafetyReport{};
  for (int k = 0; k < substeps_; ++k) {
    if (!substep_participants_.empty()) {
      const SensorFrame frame = backend_.read();
      JointCommand command = record_.command;
      bool replaced = false;
      for (SubstepParticipant* participant : substep_participants_) replaced |= participant->on_substep(frame, command);
      if (replaced) {
        record_.substep_safety.flags |=
            guard_command(record_.state, command, guard_limits_, record_.health.protection).flags;
        backend_.write(command);
      }
    }
    pace_until(backend_.time_s());
    backend_.advance(substep_s);
  }
}

void ControlLoop::pace_until(double robot_time_s) {
  if (pace_speed_ <= 0.0) return;
  using Clock = std::chrono::steady_clock;
  const double wall_offset_s = (robot_time_s - pace_robot_start_s_) / pace_speed_;
  const Clock::time_point deadline =
      pace_wall_start_ + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(wall_offset_s));
  const double substep_wall_s = period_s_ / substeps_ / pace_speed_;
  const double late_wall_s = std::chrono::duration<double>(Clock::now() - deadline).count();
  if (late_wall_s > kPaceCatchUpLimitPeriods * period_s_ / pace_speed_) {
    // the schedule resumes from now: the robot time lost is not run in a burst
    pace_wall_start_ += std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(late_wall_s));
    ++late_substeps_;
    ++pace_slips_;
    slipped_wall_s_ += late_wall_s;
    return;
  }
  if (late_wall_s > substep_wall_s) {
    ++late_substeps_;
    return;
  }
  // in slices, so a slowly paced loop (--speed 0.0001: seconds per substep) still stops at once
  constexpr std::chrono::milliseconds kLongestNap{20};
  for (Clock::time_point now = Clock::now(); now < deadline; now = Clock::now()) {
    if (pace_stop_ != nullptr && pace_stop_->load(std::memory_order_relaxed)) return;
    std::this_thread::sleep_until(std::min(deadline, now + kLongestNap));
  }
}

RunStats ControlLoop::run(const RunOptions& options, const std::atomic<bool>& stop) {
  using Clock = std::chrono::steady_clock;
  RunStats stats;
  pace_speed_ = options.speed;
  pace_stop_ = &stop;
  pace_robot_start_s_ = backend_.time_s();
  const Clock::time_point run_wall_start = Clock::now();
  pace_wall_start_ = run_wall_start;  // moves on at each slip
  late_substeps_ = 0;
  pace_slips_ = 0;
  slipped_wall_s_ = 0.0;
  last_tick_wall_ = {};
  while (!stop.load(std::memory_order_relaxed)) {
    const double elapsed = backend_.time_s() - pace_robot_start_s_;
    if (options.duration_s >= 0.0 && elapsed >= options.duration_s - 1e-9) break;
    tick();
    ++stats.ticks;
  }
  stats.late_substeps = late_substeps_;
  stats.pace_slips = pace_slips_;
  stats.slipped_wall_s = slipped_wall_s_;
  stats.robot_time_s = backend_.time_s() - pace_robot_start_s_;
  stats.wall_time_s = std::chrono::duration<double>(Clock::now() - run_wall_start).count();
  pace_speed_ = 0.0;
  pace_stop_ = nullptr;
  return stats;
}

}  // namespace cerebellum
