#include "modes/command_inbox.hpp"

namespace cerebellum {

bool CommandInbox::push(const TimedCommand& input) {
  const auto source = static_cast<std::size_t>(input.source);
  if (source >= kHighLevelSourceCount) return false;
  if (!producers_[source].held_by_caller()) {
    counters_[source].wrong_thread.fetch_add(1, std::memory_order_relaxed);
    return false;
  }
  if (!rings_[source].try_push(input)) {
    counters_[source].ring_overflow.fetch_add(1, std::memory_order_relaxed);
    return false;
  }
  counters_[source].submitted.fetch_add(1, std::memory_order_relaxed);
  return true;
}

}  // namespace cerebellum
