#include "modes/command_inbox.hpp"

namespace cerebellum {

bool CommandInbox::push(const TimedCommand& input) {
  const auto source = static_cast<std::size_t>(input.source);
  if (source >= kHighLevelSourceCount) return false;
  const std::thread::id me = std::this_thread::get_id();
  std::thread::id owner = producers_[source].load(std::memory_order_acquire);
  // the first pusher claims the source; exactly one thread wins the claim
  if (owner == std::thread::id{} &&
      producers_[source].compare_exchange_strong(owner, me, std::memory_order_acq_rel)) {
    owner = me;
  }
  if (owner != me) {
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
