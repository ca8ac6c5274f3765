// Plays a planned flip (flip_trajectory) as joint commands: at time t the plan's joint targets,
// rates and feed-forward torques, linearly between its knots, the two legs of a pair alike, a
// joint PD around them; the abad joints held straight (the plan is planar). Past the plan's end
// the legs hold its last pose (the tuck is planned into the flight's end: legs at the landing pose).
#pragma once

#include "control/jump/flip_trajectory.hpp"
#include "core/types.hpp"

namespace cerebellum {

struct FlipPlayGains {
  // the PD around the plan: stiff enough to keep the legs on their path where the model and the
  // body differ, soft enough that the feed-forward torques do the work
  double kp = 40.0;
  double kd = 1.0;
  double abad_kp = 60.0;
  double abad_kd = 1.5;
};

// the plan at t_s (clamped to its span); the command for every joint
JointCommand flip_play_command(const FlipTrajectory& trajectory, double t_s, const FlipPlayGains& gains = {});

// the plan's sample at t_s, interpolated (phase: the earlier knot's)
FlipSample flip_sample_at(const FlipTrajectory& trajectory, double t_s);

inline double flip_duration_s(const FlipTrajectory& trajectory) { return trajectory.samples.back().time_s; }

}  // namespace cerebellum
