// The single producer of a single-producer ring, enforced: the first thread that produces claims
// the ring; any other thread is refused (and its caller counts it) instead of racing the owner on
// the ring's head, which tears records and can leave the consumer draining stale slots for good.
#pragma once

#include <atomic>
#include <thread>

namespace cerebellum {

class ProducerClaim {
 public:
  // true when the calling thread is (or has just become) the producer
  bool held_by_caller() {
    const std::thread::id me = std::this_thread::get_id();
    std::thread::id owner = owner_.load(std::memory_order_acquire);
    if (owner == std::thread::id{} && owner_.compare_exchange_strong(owner, me, std::memory_order_acq_rel)) {
      return true;
    }
    return owner == me;
  }

 private:
  std::atomic<std::thread::id> owner_{};
};

}  // namespace cerebellum
