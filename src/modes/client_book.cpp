#include "modes/client_book.hpp"

namespace cerebellum {

void ClientBook::refused(HighLevelSource source, const ClientNote& note) {
  counters(source).banned_transitions.fetch_add(1, std::memory_order_relaxed);
  refusals(source).try_push(note);
}

void ClientBook::refused_not_holder(HighLevelSource source, const HighLevelCommand& command, int from_mode,
                                    HighLevelSource holder) {
  counters(source).refused_not_holder.fetch_add(1, std::memory_order_relaxed);
  int& last = refused_life_count_[index(source)];
  if (last == command.life_count) return;
  last = command.life_count;
  refusals(source).try_push({command.mode, command.gait_id, from_mode,
                             source == HighLevelSource::AlienGoUdp
                                 ? "another high-level client holds the robot (HighCmd)"
                                 : "another high-level client holds the robot",
                             source_name(holder)});
}

void ClientBook::clamped(HighLevelSource source, const HighLevelCommand& command, const char* reason) {
  counters(source).clamped.fetch_add(1, std::memory_order_relaxed);
  refusals(source).try_push({command.mode, command.gait_id, command.mode, reason, nullptr, true});
}

void ClientBook::motion_dropped(HighLevelSource source, const HighLevelCommand& command) {
  counters(source).motions_dropped.fetch_add(1, std::memory_order_relaxed);
  refusals(source).try_push({command.mode, command.gait_id, static_cast<int>(ModeId::Motion),
                             "a motion is running: mode-62 commands are dropped until it ends", nullptr});
}

}  // namespace cerebellum
