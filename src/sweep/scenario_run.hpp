// One run of a scenario: the MC in-process on the simulated robot, in lockstep (no sockets, no
// wall clock), driven by the scenario's script or soak, shoved by its pushes, faulted by its
// faults, and judged on the simulator's truth.
#pragma once

#include <functional>

#include "loop/mc.hpp"
#include "loop/mc_config.hpp"
#include "sweep/run_result.hpp"
#include "sweep/scenario.hpp"

namespace cerebellum {

// the MC's configuration of a scenario: its robot.config file (or the defaults) with the
// scenario's own robot keys; throws ConfigError for a bad configuration file
McConfig scenario_config(const Scenario& scenario);

// what a caller attaches to the run's MC (a video recorder for a replay): started once the MC is
// built, before its first tick; ending after its last tick, while the MC still exists
struct RunAttachments {
  std::function<void(Mc&)> started;
  std::function<void(Mc&)> ending;
};

// throws ConfigError / std::runtime_error when the robot cannot be built
RunResult run_scenario(const Scenario& scenario, const RunAttachments& attachments = {});

}  // namespace cerebellum
