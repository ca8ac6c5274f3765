#include "loop/simulated_robot.hpp"

namespace cerebellum {

McRobot make_simulated_robot(const MujocoBackendConfig& config, std::vector<TimedFault> faults) {
  auto simulation = std::make_unique<MujocoBackend>(config);
  Simulation* handle = simulation.get();
  auto injector = std::make_unique<FaultInjectingBackend>(std::move(simulation), handle, std::move(faults));
  FaultInjectingBackend* faults_handle = injector.get();
  return {std::move(injector), handle, faults_handle};
}

Mc make_simulated_mc(const McConfig& config, std::vector<TimedFault> faults) {
  return Mc(config, make_simulated_robot(config.robot, std::move(faults)));
}

}  // namespace cerebellum
