#include "io/robot_link/robot_link_log.hpp"

namespace cerebellum {

void log_link_changes(const RobotLinkStatus& was, const RobotLinkStatus& is, double robot_time_s,
                      double link_timeout_s, const RobotLinkWords& words, double now_s, RateLimitedLog& events,
                      std::FILE* out) {
  using ull = unsigned long long;
  char line[256];
  if (is.link_losses > was.link_losses) {
    std::snprintf(line, sizeof line,
                  "link lost at %.3f s robot time: no %s for %.1f ms (limit %.1f ms); damping the legs (loss %llu)",
                  robot_time_s, words.state, is.link_silent_s * 1e3, link_timeout_s * 1e3, ull(is.link_losses));
    events.line(now_s, line);
  } else if (was.link_lost && !is.link_lost && was.link_losses > 0) {
    std::snprintf(line, sizeof line, "link back at %.3f s robot time", robot_time_s);
    events.line(now_s, line);
  }
  if (is.jumped_states > was.jumped_states) {
    std::snprintf(line, sizeof line,
                  "%s refused at %.3f s robot time: a joint angle moved %.3f rad since the last state taken, "
                  "more than a joint can (%llu refused so far)",
                  words.joints, robot_time_s, is.last_jump_rad, ull(is.jumped_states));
    events.line(now_s, line);
  }
  if (is.repeated_states > was.repeated_states) {
    std::snprintf(line, sizeof line,
                  "%llu states at %.3f s robot time repeated the one before in every value: not fresh (%llu so far)",
                  ull(is.repeated_states - was.repeated_states), robot_time_s, ull(is.repeated_states));
    events.line(now_s, line);
  }
  if (is.stopped && !was.stopped) {
    // once per run: never rate limited away
    std::fprintf(out,
                 "%s: motor error (motors 0x%03x) at %.3f s robot time: commanding stopped, damping frames "
                 "until restart\n",
                 words.robot, static_cast<unsigned>(is.error_motors), robot_time_s);
  }
  events.tick(now_s);
}

}  // namespace cerebellum
