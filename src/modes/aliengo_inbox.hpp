// The AlienGo client's way into the tick, all its transport sees of the MC: a single-producer ring
// of decoded HighCmds (the adapter's thread pushes, AlienGoSource takes them in the tick), the
// notes of what the sport session refused, and the counters.
#pragma once

#include <atomic>
#include <cstdint>
#include <optional>

#include "core/claimed_ring.hpp"
#include "core/spsc_ring.hpp"
#include "modes/aliengo_command.hpp"

namespace cerebellum {

// a HighCmd the session refused (it stays in its mode), for the adapter's thread to log
struct AlienGoRefusal {
  int mode = 0;                  // what the client asked
  int session_mode = 0;          // where the session stays
  const char* reason = nullptr;  // a static string
};

// the ring's (HighCmds handed over, dropped for arriving faster than the tick takes them, refused
// from a second thread) and the session's
struct AlienGoInboxCounters : ClaimedRingCounters {
  std::atomic<std::uint64_t> illegal_moves{0};  // refused by the vendor's mode table
};

class AlienGoInbox {
 public:
  static constexpr std::size_t kRingCapacity = 64;

  // the transport's thread (one thread): a decoded HighCmd; false when the ring is full or
  // another thread already hands over
  bool push(const AlienGoCommand& command) { return ring_.push(command); }
  // the transport's thread (the one consumer): the next refusal not yet logged
  std::optional<AlienGoRefusal> next_refusal() { return refusals_.try_pop(); }
  // any thread
  const AlienGoInboxCounters& counters() const { return ring_.counters(); }

  // loop thread
  std::optional<AlienGoCommand> take() { return ring_.try_pop(); }
  void refused(const AlienGoRefusal& refusal) {
    ring_.counters().illegal_moves.fetch_add(1, std::memory_order_relaxed);
    refusals_.try_push(refusal);
  }

 private:
  ClaimedRing<AlienGoCommand, kRingCapacity, AlienGoInboxCounters> ring_;
  SpscRing<AlienGoRefusal, 16> refusals_;
};

}  // namespace cerebellum
