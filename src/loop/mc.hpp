// The MC assembled from its configuration on a given robot: estimator, modes, state machine,
// arbiter and loop. Client interfaces attach to it (arbiter sources, loop observers, substep
// participants); tools and tests reach a simulated robot through simulation().
#pragma once

#include <memory>

#include "loop/control_loop.hpp"
#include "loop/mc_config.hpp"
#include "loop/mc_robot.hpp"
#include "estimation/body_state_estimator.hpp"
#include "modes/aliengo_source.hpp"
#include "modes/high_level_machine.hpp"
#include "modes/mode_set.hpp"
#include "modes/source_arbiter.hpp"
#include "motions/user_gait_upload.hpp"

namespace cerebellum {

// the command the MC runs by itself at start
HighLevelCommand startup_command(Startup startup);

class Mc {
 public:
  // robot.backend: what the loop reads and drives (owned); robot.simulation: the same robot's
  // simulation handle, or nullptr (throws std::invalid_argument without a backend)
  Mc(const McConfig& config, McRobot robot);
  Mc(const Mc&) = delete;
  Mc& operator=(const Mc&) = delete;

  RobotBackend& backend() { return *backend_; }
  bool simulated() const { return simulation_ != nullptr; }
  // throws std::logic_error when the robot is not simulated
  Simulation& simulation();
  // the robot's fault injector, or nullptr when it has none
  FaultInjectingBackend* faults() { return faults_; }
  HighLevelMachine& machine() { return machine_; }
  // the AlienGo client's stage in the tick: its transport hands decoded HighCmds to it
  AlienGoSource& aliengo_source() { return aliengo_; }
  // where the high-level interface hands over uploaded user gaits
  UserGaitSlot& user_gait_slot() { return modes_.user_gait_slot(); }
  // where a transport hands received user-gait files (checked, stored, built into the slot)
  UserGaitUpload& user_gait_upload() { return user_gait_upload_; }
  // what each high-level client's transport is given: its ring into the tick, its refusals, its
  // counters (the AlienGo transport also gets aliengo_source().inbox())
  ClientPort client_port(HighLevelSource source) { return machine_.port(source); }
  SourceArbiter& arbiter() { return arbiter_; }
  ControlLoop& loop() { return loop_; }
  const McConfig& config() const { return config_; }
  const WalkingGaits& walking() const { return modes_.walking(); }
  const ModeSet& modes() const { return modes_; }

 private:
  McConfig config_;
  std::unique_ptr<RobotBackend> backend_;
  Simulation* simulation_;
  FaultInjectingBackend* faults_;
  BodyStateEstimator estimator_;
  ModeSet modes_;
  UserGaitUpload user_gait_upload_;
  HighLevelMachine machine_;
  AlienGoSource aliengo_;
  SourceArbiter arbiter_;
  ControlLoop loop_;
};

}  // namespace cerebellum
