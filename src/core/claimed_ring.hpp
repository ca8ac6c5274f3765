// A single-producer ring whose one producer is enforced (ProducerClaim) and whose hand-overs are
// counted: the way every client's commands reach the loop thread (the machine's per-client
// inboxes, the AlienGo client's stage). Counters may extend ClaimedRingCounters with figures of
// their own (the consumer's), reached through counters().
#pragma once

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <optional>

#include "core/producer_claim.hpp"
#include "core/spsc_ring.hpp"

namespace cerebellum {

// written by the producer, read by anyone
struct ClaimedRingCounters {
  std::atomic<std::uint64_t> submitted{0};      // pushed into the ring
  std::atomic<std::uint64_t> ring_overflow{0};  // the ring was full: the producer sends faster than the consumer takes
  std::atomic<std::uint64_t> wrong_thread{0};   // refused: a second thread pushed
};

template <typename T, std::size_t Capacity, typename Counters = ClaimedRingCounters>
class ClaimedRing {
 public:
  // producer side: the first thread that pushes owns the ring; false when refused or full
  bool push(const T& value) {
    if (!producer_.held_by_caller()) {
      counters_.wrong_thread.fetch_add(1, std::memory_order_relaxed);
      return false;
    }
    if (!ring_.try_push(value)) {
      counters_.ring_overflow.fetch_add(1, std::memory_order_relaxed);
      return false;
    }
    counters_.submitted.fetch_add(1, std::memory_order_relaxed);
    return true;
  }
  // consumer side
  std::optional<T> try_pop() { return ring_.try_pop(); }

  const Counters& counters() const { return counters_; }
  Counters& counters() { return counters_; }

 private:
  ProducerClaim producer_;
  SpscRing<T, Capacity> ring_;
  Counters counters_;
};

}  // namespace cerebellum
