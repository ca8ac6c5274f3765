// A high-level client inside the MC's own process, in lockstep robot time: it hands commands to
// the state machine the way a real client's messages arrive (a new life_count, then the same
// command repeated as heartbeat every 0.1 s). For tests, benchmarks and demos without transport.
#pragma once

#include "loop/mc.hpp"
#include "control/locomotion/gait_table.hpp"

namespace cerebellum {

class LockstepClient {
 public:
  explicit LockstepClient(Mc& mc) : mc_(mc) {}

  // send a new command and keep it alive while the robot runs for seconds; each_tick(record)
  // sees every cycle
  template <typename EachTick>
  void run(HighLevelCommand command, double seconds, EachTick&& each_tick) {
    command.life_count = ++life_count_ % 128;
    const double end = mc_.backend().time_s() + seconds - 1e-9;
    double next_send = mc_.backend().time_s();
    while (mc_.backend().time_s() < end) {
      if (mc_.backend().time_s() >= next_send - 1e-9) {
        mc_.machine().submit(command, mc_.backend().time_s());
        next_send += kHeartbeatPeriodS;
      }
      each_tick(mc_.loop().tick());
    }
  }
  void run(const HighLevelCommand& command, double seconds) {
    run(command, seconds, [](const CycleRecord&) {});
  }

  static constexpr double kHeartbeatPeriodS = kClientHeartbeatPeriodS;

 private:
  Mc& mc_;
  int life_count_ = 0;
};

// a command with the fields most callers set
inline HighLevelCommand high_level_command(ModeId mode, int gait, double vx = 0.0, double vy = 0.0,
                                           double yaw_rate = 0.0) {
  HighLevelCommand c;
  c.mode = static_cast<int>(mode);
  c.gait_id = gait;
  c.vel_des = {static_cast<float>(vx), static_cast<float>(vy), static_cast<float>(yaw_rate)};
  // a walking command carries the gait's usual swing height, as the vendor's examples send one
  // (0 would be taken as commanded: the 5 mm floor of kStepHeightRange)
  const GaitSpec* spec = find_gait(gait);
  if (mode == ModeId::Locomotion && spec != nullptr) {
    const auto step_height_m = static_cast<float>(spec->default_step_height_m);
    c.step_height = {step_height_m, step_height_m};
  }
  return c;
}

}  // namespace cerebellum
