// A shove on a standing MC, in lockstep on the simulation's truth: what the push-recovery tests
// (mc_push_recovery_test.cpp, and the long ones in mc_push_recovery_long_test.cpp) watch.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>

#include "loop/lockstep_client.hpp"
#include "loop/simulated_robot.hpp"
#include "mc_fixture.hpp"

namespace cerebellum {
namespace push_recovery_testing {

using testing::truth_tilt_rad;

struct ShoveOutcome {
  double largest_tilt_rad = 0.0;
  bool a_foot_lifted = false;
  int final_mode = 0;
  double final_speed_m_s = 0.0;
  bool all_feet_down_at_the_end = false;
  double moved_m = 0.0;
  // the estimate's largest horizontal velocity error while the force acts (m/s)
  double largest_velocity_error_m_s = 0.0;
};

// stands up, holds the stand gait 2 s, pushes the trunk along a world direction (unit; the robot
// faces +x) with impulse_n_s spread over push_s, and watches for settle_s; stand_extra_s holds the
// stand longer before the push (another moment of the simulation)
inline ShoveOutcome shove(int gait_id, double impulse_n_s, double push_s, double settle_s,
                   const std::array<double, 2>& direction = {0.0, 1.0}, double stand_extra_s = 0.0) {
  McConfig config = default_config();
  config.startup = Startup::Off;
  Mc mc = make_simulated_mc(config);
  LockstepClient client(mc);
  client.run(high_level_command(ModeId::RecoveryStand, 0), 3.0);
  const HighLevelCommand stand = high_level_command(ModeId::Locomotion, gait_id);
  client.run(stand, 2.0 + stand_extra_s);
  const std::array<double, 3> start = mc.simulation().ground_truth().position;
  const double force_n = impulse_n_s / push_s;
  mc.simulation().request_force_pulse({{direction[0] * force_n, direction[1] * force_n, 0.0}, push_s});
  ShoveOutcome outcome;
  const double push_end_s = mc.simulation().time_s() + push_s;
  client.run(stand, push_s + settle_s, [&](const CycleRecord& record) {
    const GroundTruth truth = mc.simulation().ground_truth();
    outcome.largest_tilt_rad = std::max(outcome.largest_tilt_rad, truth_tilt_rad(truth));
    for (bool contact : truth.foot_contact) outcome.a_foot_lifted |= !contact;
    if (mc.simulation().time_s() <= push_end_s) {
      const double error = std::hypot(record.state.velocity_world.x() - truth.velocity_world[0],
                                      record.state.velocity_world.y() - truth.velocity_world[1]);
      outcome.largest_velocity_error_m_s = std::max(outcome.largest_velocity_error_m_s, error);
    }
  });
  const GroundTruth truth = mc.simulation().ground_truth();
  outcome.final_mode = mc.machine().status().mode;
  outcome.final_speed_m_s = std::hypot(truth.velocity_world[0], truth.velocity_world[1]);
  outcome.all_feet_down_at_the_end =
      truth.foot_contact[0] && truth.foot_contact[1] && truth.foot_contact[2] && truth.foot_contact[3];
  outcome.moved_m = direction[0] * (truth.position[0] - start[0]) + direction[1] * (truth.position[1] - start[1]);
  return outcome;
}

}  // namespace push_recovery_testing
}  // namespace cerebellum
