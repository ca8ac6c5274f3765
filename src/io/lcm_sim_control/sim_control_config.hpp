// Configuration of the simulation's control channel (config section `sim_command:`).
#pragma once

namespace cerebellum {

struct SimControlConfig {
  // sim_command in, sim_command_result out, on the high-level odometry URL (port 7667); the
  // simulation's own channel (pushes), never the MC's
  bool enabled = true;
};

}  // namespace cerebellum
