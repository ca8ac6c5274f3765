#include "backend/latent_link_backend.hpp"

#include <stdexcept>

namespace cerebellum {

LatentLinkBackend::LatentLinkBackend(std::unique_ptr<RobotBackend> inner, LinkLatencyTicks latency)
    : inner_(std::move(inner)) {
  if (latency.command_ticks < 0 || latency.state_ticks < 0) {
    throw std::invalid_argument("LatentLinkBackend: latencies are whole ticks, 0 or more");
  }
  states_.resize(static_cast<std::size_t>(latency.state_ticks) + 1);
  commands_.resize(static_cast<std::size_t>(latency.command_ticks));
}

SensorFrame LatentLinkBackend::read() {
  const std::size_t size = states_.size();
  states_[states_seen_ % size] = inner_->read();
  ++states_seen_;
  // the slot after the newest holds the frame size - 1 reads older, once that many were read
  const std::size_t oldest = states_seen_ < size ? 0 : states_seen_ % size;
  return states_[oldest];
}

void LatentLinkBackend::write(const JointCommand& command) {
  const std::size_t size = commands_.size();
  if (size == 0) {
    inner_->write(command);
    return;
  }
  JointCommand& slot = commands_[commands_seen_ % size];
  // the slot holds the command written size writes ago: the robot gets it now
  if (commands_seen_ >= size) inner_->write(slot);
  slot = command;
  ++commands_seen_;
}

}  // namespace cerebellum
