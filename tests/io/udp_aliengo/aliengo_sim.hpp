// The MC in lockstep with an AlienGo client streaming a HighCmd every tick into its stage in the
// tick (the path a UDP client's decoded commands take, without the socket), judged on the
// simulator's truth.
#pragma once

#include <Eigen/Geometry>
#include <cmath>

#include "loop/simulated_robot.hpp"
#include "backend/sim_fixture.hpp"
#include "modes/aliengo_source.hpp"

namespace cerebellum::testing {

// the MC's defaults, standing the robot up by itself at start (the AlienGo tests start standing)
inline McConfig standing_config() {
  McConfig config = default_config();
  config.startup = Startup::Stand;
  return config;
}

struct AlienGoSim {
  explicit AlienGoSim(const McConfig& config = standing_config()) : mc(make_simulated_mc(config)) {}

  double time_s() { return mc.backend().time_s(); }
  const RobotState& state() { return mc.loop().last_cycle().state; }
  const HighLevelStatus& status() { return mc.machine().status(); }

  // one tick with this HighCmd received just before it; refused: whether the session refused it
  void tick(const AlienGoCommand& command) {
    const std::uint64_t illegal = mc.aliengo_source().counters().illegal_moves.load();
    mc.aliengo_source().push(command);
    mc.loop().tick();
    refused = mc.aliengo_source().counters().illegal_moves.load() > illegal;
  }
  // one tick without a HighCmd (the client is silent)
  void silent_tick() { mc.loop().tick(); }
  const AlienGoSession& session() { return mc.aliengo_source().session(); }
  // the mode HighState reports
  int reported_mode() { return mc.loop().last_cycle().high_level.aliengo_mode; }
  void stream(const AlienGoCommand& command, double seconds) {
    const double end = time_s() + seconds - 1e-9;
    while (time_s() < end) tick(command);
  }
  void silence(double seconds) {
    const double end = time_s() + seconds - 1e-9;
    while (time_s() < end) silent_tick();
  }
  // the MC's own start (it stands up by itself), no client yet
  void idle(double seconds) {
    const double end = time_s() + seconds - 1e-9;
    while (time_s() < end) mc.loop().tick();
  }

  // simulator truth
  GroundTruth truth() { return mc.simulation().ground_truth(); }
  Eigen::Vector3d true_rpy() { return truth_rpy(truth()); }
  Eigen::Vector2d true_xy() { return {truth().position[0], truth().position[1]}; }
  double true_height() { return truth().position[2]; }
  bool all_feet_down() {
    const GroundTruth t = truth();
    return t.foot_contact[0] && t.foot_contact[1] && t.foot_contact[2] && t.foot_contact[3];
  }

  Mc mc;
  bool refused = false;
};

inline AlienGoCommand high_cmd(int mode) {
  AlienGoCommand c;
  c.mode = mode;
  return c;
}

}  // namespace cerebellum::testing
