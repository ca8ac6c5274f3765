#include "modes/command_inbox.hpp"

namespace cerebellum {

bool CommandInbox::push(const TimedCommand& input) {
  const auto source = static_cast<std::size_t>(input.source);
  return source < kHighLevelSourceCount && rings_[source].push(input);
}

}  // namespace cerebellum
