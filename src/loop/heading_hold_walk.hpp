// A client in the MC's own process that walks the robot straight along a heading, as a person
// holding a direction would: every heartbeat period its yaw rate command corrects the robot's own
// yaw estimate (from the cycle record, never the simulator's truth). For the terrain tests and
// benchmarks, where a drift of a few degrees would walk the robot off a 4 m wide ramp.
#pragma once

#include <cmath>

#include "loop/lockstep_client.hpp"

namespace cerebellum {

class HeadingHoldWalk {
 public:
  // walk: the mode-11 command (gait, forward and sideways speed); its yaw rate is the client's
  HeadingHoldWalk(Mc& mc, const HighLevelCommand& walk, double heading_rad = 0.0)
      : client_(mc), walk_(walk), heading_rad_(heading_rad) {}

  // walks for up to seconds of robot time; each_tick(record) sees every cycle and returns false
  // to end the walk there. Returns the robot time walked
  template <typename EachTick>
  double run(double seconds, EachTick&& each_tick) {
    double walked_s = 0.0;
    bool going = true;
    while (going && walked_s < seconds - 1e-9) {
      walk_.vel_des[2] = static_cast<float>(kHeadingGainPerS * wrapped(heading_rad_ - yaw_estimate_rad_));
      client_.run(walk_, LockstepClient::kHeartbeatPeriodS, [&](const CycleRecord& record) {
        if (!going) return;
        yaw_estimate_rad_ = record.state.rpy.z();
        walked_s += record.state.time_s - (last_time_s_ < 0.0 ? record.state.time_s : last_time_s_);
        last_time_s_ = record.state.time_s;
        going = each_tick(record);
      });
    }
    return walked_s;
  }

  // rad/s of yaw rate per rad of heading error: a second to take out a drift, gentle beside the gait
  static constexpr double kHeadingGainPerS = 1.0;

 private:
  static double wrapped(double angle_rad) { return std::remainder(angle_rad, 2.0 * 3.14159265358979323846); }

  LockstepClient client_;
  HighLevelCommand walk_;
  double heading_rad_;
  double yaw_estimate_rad_ = 0.0;
  double last_time_s_ = -1.0;
};

}  // namespace cerebellum
