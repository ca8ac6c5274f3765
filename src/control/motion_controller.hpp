// The decide + control stage of the cycle: robot state in, joint command (and the contacts it
// plans, for the estimator at the next tick) out.
#pragma once

#include "core/contact_plan.hpp"
#include "core/high_level_command.hpp"
#include "core/robot_state.hpp"
#include "core/types.hpp"
#include "safety/health_monitor.hpp"

namespace cerebellum {

class MotionController {
 public:
  virtual ~MotionController() = default;
  // called every tick, in the loop thread; must not allocate or print, and must not wait for
  // anything but the MPC solve it posted at an earlier tick (MpcWorker: docs/architecture.md)
  virtual void compute(const RobotState& state, JointCommand& command) = 0;
  // called every tick before compute(), also while the state is not valid (compute() is not then):
  // the health protection of this tick, which the guard enforces on the command whatever it is
  virtual void observe_health(const HealthVerdict& /*verdict*/) {}
  // the contacts the last compute() planned for the next tick; none unless a gait steps
  virtual ContactPlan contact_plan() const { return std::nullopt; }
  // called every tick after compute() (and in its place while the state is not valid): the
  // high-level state for the cycle record; controllers without one leave the report as it is
  virtual void report(HighLevelReport& /*report*/) const {}
};

}  // namespace cerebellum
