// Configuration of the ground-truth channel `sim_truth` (config section `sim_truth:`).
#pragma once

namespace cerebellum {

struct SimTruthConfig {
  // messages per second of simulated time; 0 turns the channel off. It goes out on the high-level
  // interface's odometry URL (port 7667), whether or not that interface is enabled.
  double rate_hz = 50.0;
};

inline constexpr double kSimTruthRateMaxHz = 500.0;  // one message per tick at the default loop

}  // namespace cerebellum
