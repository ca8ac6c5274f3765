#include "loop/simulated_robot.hpp"

namespace cerebellum {

McRobot make_simulated_robot(const MujocoBackendConfig& config, std::vector<TimedFault> faults,
                             LinkLatencyTicks latency) {
  auto simulation = std::make_unique<MujocoBackend>(config);
  Simulation* handle = simulation.get();
  auto injector = std::make_unique<FaultInjectingBackend>(std::move(simulation), handle, std::move(faults));
  FaultInjectingBackend* faults_handle = injector.get();
  // the faults are the robot's; the latency is the link's, between the robot and the MC
  if (!latency.any()) return {std::move(injector), handle, faults_handle};
  return {std::make_unique<LatentLinkBackend>(std::move(injector), latency), handle, faults_handle};
}

Mc make_simulated_mc(const McConfig& config, std::vector<TimedFault> faults) {
  return Mc(config, make_simulated_robot(config.robot, std::move(faults), config.simulated_link_latency));
}

}  // namespace cerebellum
