// The single owner of the control tick: read -> estimate -> decide/control -> guard -> write,
// then let the robot run one period. Paced in real time (scaled) or run lockstep at full speed.
#pragma once

#include <atomic>
#include <cstdint>
#include <vector>

#include "backend/robot_backend.hpp"
#include "control/motion_controller.hpp"
#include "core/robot_state.hpp"
#include "estimation/state_estimator.hpp"
#include "safety/command_guard.hpp"

namespace cerebellum {

// everything one cycle saw and did
struct CycleRecord {
  std::uint64_t tick = 0;
  RobotState state;
  JointCommand command;  // as written to the robot, after the guard
  SafetyReport safety;
};

// sees every cycle record in the loop thread; must only copy (no I/O, no blocking)
class CycleObserver {
 public:
  virtual ~CycleObserver() = default;
  virtual void on_cycle(const CycleRecord& record) = 0;
};

struct RunOptions {
  double duration_s = -1.0;  // simulated/robot seconds to run; < 0 runs until stopped
  double speed = 1.0;        // real-time factor to pace at; <= 0 runs as fast as possible (lockstep)
};

struct RunStats {
  std::uint64_t ticks = 0;
  std::uint64_t late_ticks = 0;  // paced mode: ticks that started after their deadline
  double robot_time_s = 0.0;
  double wall_time_s = 0.0;
};

class ControlLoop {
 public:
  ControlLoop(RobotBackend& backend, StateEstimator& estimator, MotionController& controller,
              const GuardLimits& guard_limits, double period_s);

  void add_observer(CycleObserver& observer);
  // one full cycle
  const CycleRecord& tick();
  RunStats run(const RunOptions& options, const std::atomic<bool>& stop);

  double period_s() const { return period_s_; }
  const CycleRecord& last_cycle() const { return record_; }

 private:
  RobotBackend& backend_;
  StateEstimator& estimator_;
  MotionController& controller_;
  GuardLimits guard_limits_;
  double period_s_;
  CycleRecord record_;
  std::vector<CycleObserver*> observers_;
};

}  // namespace cerebellum
