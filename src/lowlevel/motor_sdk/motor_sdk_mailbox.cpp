#include "lowlevel/motor_sdk/motor_sdk_mailbox.hpp"

#include <cmath>

#include "safety/command_finite.hpp"

namespace cerebellum {

PushResult MotorSdkMailbox::push(const JointCommand& sdk_frame, double received_s) {
  if (!command_is_finite(sdk_frame) || !std::isfinite(received_s)) {
    non_finite_.fetch_add(1, std::memory_order_relaxed);
    return PushResult::NonFinite;
  }
  if (!ring_.try_push(StampedFrame{sdk_frame, received_s})) return PushResult::Full;
  accepted_.fetch_add(1, std::memory_order_release);
  return PushResult::Accepted;
}

std::optional<StampedFrame> MotorSdkMailbox::pop() {
  std::optional<StampedFrame> frame = ring_.try_pop();
  if (frame) popped_.fetch_add(1, std::memory_order_relaxed);
  return frame;
}

bool MotorSdkMailbox::has_pending() const {
  // popped can pass accepted for a moment (the count follows the push): that reads as empty
  return accepted_.load(std::memory_order_acquire) > popped_.load(std::memory_order_relaxed);
}

}  // namespace cerebellum
