// One playback of a flip file on the simulated robot (MujocoBackend: the motors' law, torque
// limits and torque-speed curve at the physics rate), open loop as the MC would play it: the robot
// placed in the plan's start pose, settled, the plan played (flip_play_command), then the landing
// pose held. Judged on the simulator's truth. Shared by bench/flip_playback_bench and its test.
#pragma once

#include <cstdint>
#include <string>

#include "control/jump/flip_player.hpp"

namespace cerebellum {

struct FlipPlaybackSetup {
  std::string model_path;
  // 0: the plan's own start; otherwise seeded perturbations: each joint's start within
  // +-0.03 rad, the trunk's pitch within +-0.02 rad, each foot's friction 0.8 within +-10 %
  std::uint64_t seed = 0;
  FlipPlayGains gains;
  double settle_s = 0.5;
  double hold_s = 1.5;  // after the plan: the landing pose held this long before judging
  // > 0: a line to stdout every this many seconds of the playback (time, trunk x, z, pitch
  // turned, roll, the feet on the ground), to see where the body leaves the plan
  double trace_every_s = 0.0;
};

struct FlipPlaybackOutcome {
  double pitch_turned_rad = 0.0;     // the trunk's pitch rate integrated over the plan and the hold
  double pitch_at_plan_end_rad = 0.0;
  double peak_torque_nm = 0.0;       // the largest torque a motor applied
  double peak_rear_knee_nm = 0.0;
  double landing_distance_m = 0.0;   // horizontal, trunk at the end from the trunk at the start
  double flight_s = 0.0;             // the longest time with no foot on the ground
  double temperature_rise_c = 0.0;   // the hottest motor winding's rise over the playback (deg C)
  bool landed_upright = false;       // at the end: trunk above 0.15 m, tilted less than 0.5 rad from upright
};

FlipPlaybackOutcome play_flip_on_simulation(const FlipTrajectory& trajectory, const FlipPlaybackSetup& setup);

}  // namespace cerebellum
