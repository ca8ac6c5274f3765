// The last stage of every cycle: a pure function that keeps the joint command inside the
// robot's limits and replaces it with damping when it (or the state) cannot be trusted.
#pragma once

#include "core/robot_model.hpp"
#include "core/robot_state.hpp"
#include "core/types.hpp"
#include "safety/command_limits.hpp"
#include "safety/health_monitor.hpp"
#include "safety/safety_report.hpp"

namespace cerebellum {

struct GuardLimits {
  CommandLimits command;
  double damping_kd = robot::kDampingKd;  // kd of the replacement command
  HealthLimits health;
};

// clamps each field into its range (one GuardFlag per cause) or replaces the command: with joint
// damping when the health protection damps, the state is not valid or a number in the command is
// NaN/Inf; with the passive command once the protection has stopped the motors. Whoever wrote the
// command (the MC's modes or a low-level client), the protection has the last word.
SafetyReport guard_command(const RobotState& state, JointCommand& command, const GuardLimits& limits,
                           Protection protection = Protection::None);

}  // namespace cerebellum
