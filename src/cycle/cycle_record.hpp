// What one control cycle saw and did: the loop fills it each tick and hands it to its observers.
#pragma once

#include <cstdint>

#include "core/contact_plan.hpp"
#include "core/high_level_command.hpp"
#include "core/robot_readings.hpp"
#include "core/robot_state.hpp"
#include "core/types.hpp"
#include "safety/command_guard.hpp"

namespace cerebellum {

// everything one cycle saw and did
struct CycleRecord {
  std::uint64_t tick = 0;
  RobotState state;
  JointCommand command;      // as written to the robot, after the guard
  ContactPlan contact_plan;  // planned by the control stage, for the estimator at the next tick
  SafetyReport safety;
  HealthVerdict health;        // the health protection of this tick (enforced by the guard)
  HighLevelReport high_level;  // the high-level state machine after this tick (status, running command)
  // the guard over the commands substep participants wrote during this tick's period (flags OR-ed;
  // zero when none did). Filled after the observers ran: they see the previous period's here
  SafetyReport substep_safety;
  // wall time since the previous tick started, while the loop is paced (0 in lockstep and at the
  // first tick); the late substeps so far
  double loop_period_s = 0.0;
  std::uint64_t late_substeps = 0;
  // the real robot's link at this tick's read (present false on a simulation)
  RobotLinkReport link;
};

}  // namespace cerebellum
