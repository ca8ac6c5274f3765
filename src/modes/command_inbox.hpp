// Client commands on their way from the interface threads into the tick: one single-producer ring
// per high-level source, so two clients never write the same ring (a shared ring with two
// producers tore records, credited them to the wrong client and could leave the loop draining
// stale slots for good). The tick takes a bounded, fair share of each source per call, so no
// amount of input can hold the loop: a source's flood fills only its own ring and is counted there.
#pragma once

#include <array>
#include <atomic>
#include <cstddef>
#include <cstdint>

#include "core/claimed_ring.hpp"
#include "core/high_level_command.hpp"

namespace cerebellum {

// what happened to one source's input (written by its producer and the loop, read by anyone)
struct SourceInputCounters : ClaimedRingCounters {
  std::atomic<std::uint64_t> taken{0};  // taken by the tick
};

class CommandInbox {
 public:
  // commands each source may hand the tick per call of take(); kRingCapacity / kTakePerSourcePerTick
  // ticks is the longest a command can wait in a full ring
  static constexpr std::size_t kTakePerSourcePerTick = kCommandsPerSourcePerTick;
  static constexpr std::size_t kRingCapacity = 64;
  // the most records one call of take() hands out, whatever arrives
  static constexpr std::size_t kTakeBudgetPerTick = kTakePerSourcePerTick * kHighLevelSourceCount;

  // producer side: one thread per source (the first thread that pushes owns the source; any other
  // is refused and counted, never allowed to share the ring); false when refused or full
  bool push(const TimedCommand& input);

  // loop thread: hands each waiting command to take_one(const TimedCommand&), at most
  // kTakePerSourcePerTick per source, the sources interleaved one command each and the first
  // source rotating from call to call; returns how many were handed out (<= kTakeBudgetPerTick)
  template <typename TakeOne>
  std::size_t take(TakeOne&& take_one) {
    std::array<std::size_t, kHighLevelSourceCount> taken{};
    std::size_t total = 0;
    for (bool any = true; any;) {
      any = false;
      for (std::size_t k = 0; k < kHighLevelSourceCount; ++k) {
        const std::size_t source = (first_source_ + k) % kHighLevelSourceCount;
        if (taken[source] == kTakePerSourcePerTick) continue;
        const std::optional<TimedCommand> input = rings_[source].try_pop();
        if (!input) continue;
        ++taken[source];
        ++total;
        any = true;
        rings_[source].counters().taken.fetch_add(1, std::memory_order_relaxed);
        take_one(*input);
      }
    }
    first_source_ = (first_source_ + 1) % kHighLevelSourceCount;
    return total;
  }

  const SourceInputCounters& counters(HighLevelSource source) const {
    return rings_[static_cast<std::size_t>(source)].counters();
  }

 private:
  std::array<ClaimedRing<TimedCommand, kRingCapacity, SourceInputCounters>, kHighLevelSourceCount> rings_;
  std::size_t first_source_ = 0;  // loop thread
};

}  // namespace cerebellum
