#include "app/simulated_robot.hpp"

namespace cerebellum {

McRobot make_simulated_robot(const MujocoBackendConfig& config) {
  auto backend = std::make_unique<MujocoBackend>(config);
  Simulation* simulation = backend.get();
  return {std::move(backend), simulation};
}

Mc make_simulated_mc(const McConfig& config) { return Mc(config, make_simulated_robot(config.robot)); }

}  // namespace cerebellum
