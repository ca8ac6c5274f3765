// A RobotBackend around any other whose link is slow by whole control ticks, as a real robot's
// is: the robot executes each command `command_ticks` ticks after the MC wrote it and the MC
// reads the robot's state `state_ticks` ticks after it was measured. Around the simulation in
// lockstep it makes the stacked pair's latency (B's frame reaches A a tick or so late, A's
// state reaches B a tick or so late) deterministic and testable without a second process.
// One read() and one write() per tick, as the loop does; both rings are sized once.
#pragma once

#include <cstddef>
#include <memory>
#include <vector>

#include "backend/robot_backend.hpp"

namespace cerebellum {

struct LinkLatencyTicks {
  int command_ticks = 0;  // robot.command_latency_ticks
  int state_ticks = 0;    // robot.state_latency_ticks
  bool any() const { return command_ticks > 0 || state_ticks > 0; }
};

class LatentLinkBackend final : public RobotBackend {
 public:
  LatentLinkBackend(std::unique_ptr<RobotBackend> inner, LinkLatencyTicks latency);

  // the state measured state_ticks reads ago (the oldest one while fewer have been read)
  SensorFrame read() override;
  // the robot is handed the command written command_ticks writes ago; until that many have been
  // written it keeps executing what it had
  void write(const JointCommand& command) override;
  void advance(double period_s) override { inner_->advance(period_s); }
  double time_s() const override { return inner_->time_s(); }
  RobotLinkReport link_report() const override { return inner_->link_report(); }

 private:
  std::unique_ptr<RobotBackend> inner_;
  // ring of the last state_ticks + 1 frames and of the last command_ticks commands
  std::vector<SensorFrame> states_;
  std::size_t states_seen_ = 0;
  std::vector<JointCommand> commands_;
  std::size_t commands_seen_ = 0;
};

}  // namespace cerebellum
