// A simulated robot run by a state machine built from the MC's high-level modes, stepped in lockstep,
// and a scripted client that sends commands and heartbeats the way the example clients do.
// Simulator truth is read only to check results (and to act as the hand that picks the robot up).
#pragma once

#include <array>
#include <cmath>

#include <Eigen/Geometry>
#include <mujoco/mujoco.h>
#include <string>

#include "loop/control_loop.hpp"
#include "backend/mujoco_backend.hpp"
#include "backend/sim_fixture.hpp"
#include "control/stand_up_controller.hpp"
#include "estimation/body_state_estimator.hpp"
#include "modes/high_level_machine.hpp"
#include "modes/mode_set.hpp"
#include "motions/motion_gaits.hpp"
#include "motions/motion_folder.hpp"

namespace cerebellum::testing {

inline HighLevelCommand command(ModeId mode, int gait = 0) {
  HighLevelCommand c;
  c.mode = static_cast<int>(mode);
  c.gait_id = gait;
  return c;
}

// the MC's modes (modes/mode_set.hpp) with mode 11's stands on the QP stand and the shipped motions
inline ModeSetConfig mode_sim_config() {
  ModeSetConfig config;
  config.loop_period_s = 0.002;
  config.damping_kd = GuardLimits{}.damping_kd;
  config.stand_up = default_stand_up_config();
  config.locomotion_stand = LocomotionStand::Qp;
  config.motions = load_motion_library({CEREBELLUM_SOURCE_DIR "/config/motions", ""});
  attach_user_gaits(config.motions);
  return config;
}

struct ModeSim {
  explicit ModeSim(ModeId startup = ModeId::RecoveryStand, double initial_height_m = 0.3, bool sensor_noise = false,
                   unsigned noise_seed = 0)
      : backend(sim_config(initial_height_m, sensor_noise, noise_seed)),
        modes(mode_sim_config()),
        recovery_stand(modes.recovery_stand()),
        stand_gait(modes.qp_stand_gait()),
        machine(0.002, command(startup)),
        loop(backend, estimator, machine, GuardLimits{}, 0.002) {
    modes.add_to(machine);
  }

  double time_s() const { return backend.time_s(); }
  const HighLevelStatus& status() const { return machine.status(); }
  const RobotState& state() const { return loop.last_cycle().state; }

  // a new command (life_count + 1), then heartbeats every 0.1 s while the robot runs
  void send(HighLevelCommand c, double run_s) {
    c.life_count = ++life_count;
    heartbeat_ = c;
    machine.submit(c, time_s());
    run(run_s);
  }
  // runs the robot, heartbeating the last command once one was sent
  void run(double seconds) {
    const double end = time_s() + seconds - 1e-9;
    while (time_s() < end) {
      if (life_count > 0 && time_s() >= next_heartbeat_s_) {
        machine.submit(heartbeat_, time_s());
        next_heartbeat_s_ = time_s() + 0.1;
      }
      loop.tick();
    }
  }
  // runs until the predicate holds or the time is up; returns the time it took (or -1)
  template <typename Predicate>
  double run_until(Predicate done, double max_s) {
    const double start = time_s();
    while (time_s() < start + max_s - 1e-9) {
      run(0.002);
      if (done()) return time_s() - start;
    }
    return -1.0;
  }

  // simulator truth
  Eigen::Quaterniond true_orientation() const {
    const GroundTruth t = backend.ground_truth();
    return {t.quat[0], t.quat[1], t.quat[2], t.quat[3]};
  }
  Eigen::Vector3d true_rpy() const { return truth_rpy(backend.ground_truth()); }
  double true_height() const { return backend.ground_truth().position[2]; }
  Eigen::Vector3d true_position() const {
    const GroundTruth t = backend.ground_truth();
    return {t.position[0], t.position[1], t.position[2]};
  }
  // world position of a foot centre from the simulator
  Eigen::Vector3d true_foot(std::size_t leg) const {
    static const char* const kNames[kNumLegs] = {"FR_foot", "FL_foot", "RR_foot", "RL_foot"};
    const int site = mj_name2id(backend.model(), mjOBJ_SITE, kNames[leg]);
    const double* p = backend.data()->site_xpos + 3 * site;
    return {p[0], p[1], p[2]};
  }

  MujocoBackend backend;
  BodyStateEstimator estimator;
  ModeSet modes;
  const RecoveryStandMode& recovery_stand;
  const LocomotionStandGait& stand_gait;
  HighLevelMachine machine;
  ControlLoop loop;
  int life_count = 0;

 private:
  HighLevelCommand heartbeat_;
  double next_heartbeat_s_ = 0.0;
};

}  // namespace cerebellum::testing
