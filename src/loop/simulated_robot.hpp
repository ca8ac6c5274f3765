// The MuJoCo-simulated robot of a configuration: one object serving as the MC's backend and as
// the tools' simulation handle, and the MC built on it.
#pragma once

#include "loop/mc.hpp"
#include "loop/mc_robot.hpp"
#include <vector>

#include "backend/fault_injecting_backend.hpp"
#include "backend/latent_link_backend.hpp"
#include "backend/mujoco_backend.hpp"

namespace cerebellum {

// the simulation wrapped in a fault injector (faults only when the scenario or a request asks)
// and, when latency has any, in a slow link; throws std::runtime_error naming the file when the
// robot model cannot be loaded
McRobot make_simulated_robot(const MujocoBackendConfig& config, std::vector<TimedFault> faults = {},
                             LinkLatencyTicks latency = {});
// the MC on the simulated robot of config.robot (the `cerebellum sim` assembly); same throws
Mc make_simulated_mc(const McConfig& config, std::vector<TimedFault> faults = {});

}  // namespace cerebellum
