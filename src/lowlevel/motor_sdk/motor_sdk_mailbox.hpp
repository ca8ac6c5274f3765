// Hands motor SDK frames from the thread that receives them to the loop thread, without locks.
// Each frame carries the robot time at which it arrived, so every timing rule runs on robot time
// and lockstep tests are deterministic. Frames with NaN/Inf never enter.
#pragma once

#include <atomic>
#include <cstdint>
#include <optional>

#include "core/spsc_ring.hpp"
#include "core/types.hpp"

namespace cerebellum {

struct StampedFrame {
  JointCommand command;     // SDK joint convention
  double received_s = 0.0;  // robot time of arrival
};

enum class PushResult {
  Accepted,
  NonFinite,  // rejected: NaN or Inf in some field
  Full,       // rejected: the loop thread has not taken the earlier frames
};

class MotorSdkMailbox {
 public:
  static constexpr std::size_t kCapacity = 32;

  // producer side (one thread)
  PushResult push(const JointCommand& sdk_frame, double received_s);

  // consumer side (the loop thread)
  std::optional<StampedFrame> pop();
  bool has_pending() const;

  // any thread
  std::uint64_t accepted() const { return accepted_.load(std::memory_order_relaxed); }
  std::uint64_t non_finite() const { return non_finite_.load(std::memory_order_relaxed); }
  std::uint64_t dropped() const { return ring_.dropped(); }

 private:
  SpscRing<StampedFrame, kCapacity> ring_;
  std::atomic<std::uint64_t> accepted_{0};
  std::atomic<std::uint64_t> popped_{0};
  std::atomic<std::uint64_t> non_finite_{0};
};

}  // namespace cerebellum
