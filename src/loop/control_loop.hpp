// The single owner of the control tick: read -> estimate -> decide/control -> guard -> write,
// then let the robot run one period. Paced in real time (scaled) or run lockstep at full speed.
#pragma once

#include <atomic>
#include <chrono>
#include <cstdint>
#include <vector>

#include "backend/robot_backend.hpp"
#include "control/motion_controller.hpp"
#include "core/robot_state.hpp"
#include "cycle/cycle_observer.hpp"
#include "cycle/cycle_record.hpp"
#include "cycle/substep_participant.hpp"
#include "estimation/state_estimator.hpp"
#include "safety/command_guard.hpp"

namespace cerebellum {

struct RunOptions {
  double duration_s = -1.0;  // simulated/robot seconds to run; < 0 runs until stopped
  double speed = 1.0;        // real-time factor to pace at; <= 0 runs as fast as possible (lockstep)
};

struct RunStats {
  std::uint64_t ticks = 0;
  std::uint64_t late_substeps = 0;  // paced mode: substeps that started a whole substep late
  // paced mode: times the loop fell more than kPaceCatchUpLimitPeriods behind (the host stopped it)
  // and resumed from there, and the wall time so given up
  std::uint64_t pace_slips = 0;
  double slipped_wall_s = 0.0;
  double robot_time_s = 0.0;
  double wall_time_s = 0.0;
};

// A paced loop up to this many control periods behind catches up (runs its substeps without
// sleeping); further behind, the host stopped it (a VM's stolen vCPU, a debugger): it resumes the
// schedule from now instead. Catching up 50 ms would run a simulated robot 50 ms on one stale
// command, and send a real robot a burst of ticks computed on one stale state.
inline constexpr double kPaceCatchUpLimitPeriods = 2.0;

class ControlLoop {
 public:
  // period_s: the control tick; substep_s: how often substep participants run (divides period_s)
  ControlLoop(RobotBackend& backend, StateEstimator& estimator, MotionController& controller,
              const GuardLimits& guard_limits, double period_s, double substep_s = 0.001);

  void add_observer(CycleObserver& observer);
  void add_substep_participant(SubstepParticipant& participant);
  // one full cycle
  const CycleRecord& tick();
  RunStats run(const RunOptions& options, const std::atomic<bool>& stop);

  double period_s() const { return period_s_; }
  const CycleRecord& last_cycle() const { return record_; }

 private:
  void run_substeps();
  // paced runs: sleep until the wall-clock time of robot time t; no-op when not pacing
  void pace_until(double robot_time_s);

  RobotBackend& backend_;
  StateEstimator& estimator_;
  MotionController& controller_;
  GuardLimits guard_limits_;
  HealthMonitor health_;
  double period_s_;
  int substeps_;
  CycleRecord record_;
  std::vector<CycleObserver*> observers_;
  std::vector<SubstepParticipant*> substep_participants_;
  // pacing state of the current run()
  double pace_speed_ = 0.0;
  const std::atomic<bool>* pace_stop_ = nullptr;  // run()'s stop flag: a slow pace's wait ends on it
  double pace_robot_start_s_ = 0.0;
  std::chrono::steady_clock::time_point pace_wall_start_{};
  std::uint64_t late_substeps_ = 0;
  std::uint64_t pace_slips_ = 0;
  double slipped_wall_s_ = 0.0;
  std::chrono::steady_clock::time_point last_tick_wall_{};  // while paced: when the last tick started
};

}  // namespace cerebellum
