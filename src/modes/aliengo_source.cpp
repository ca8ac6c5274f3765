#include "modes/aliengo_source.hpp"

namespace cerebellum {

AlienGoSource::AlienGoSource(const AlienGoSessionConfig& config) : session_(config) {}

void AlienGoSource::submit(const AlienGoStep& step, double now_s, Commands& out, std::size_t& made) {
  if (!step.submit || made == out.size()) return;
  out[made++] = TimedCommand{*step.submit, now_s, HighLevelSource::AlienGoUdp};
  pending_mode_ = session_.mode();
  pending_mc_mode_ = step.submit->mode;
  pending_mc_gait_ = step.submit->gait_id;
}

std::size_t AlienGoSource::step(const RobotState& state, const HighLevelStatus& status, Commands& out) {
  // HighState.mode: the session's mode once the MC runs what it was translated into (so a client
  // sees when its command has been taken, or that it never is while another client holds the robot)
  if (status.mode == pending_mc_mode_ && status.gait_id == pending_mc_gait_) reported_mode_ = pending_mode_;
  const double now_s = state.time_s;
  std::size_t made = 0;
  std::size_t taken = 0;
  for (; taken < out.size(); ++taken) {
    const std::optional<AlienGoCommand> command = inbox_.take();
    if (!command) break;
    const AlienGoStep step = session_.on_command(*command, state, status.mode, status.order_process_bar, now_s);
    if (step.refusal != nullptr) {
      inbox_.refused({command->mode, session_.mode(), step.refusal});
    }
    submit(step, now_s, out, made);
  }
  if (taken == 0) submit(session_.on_silence(state, status.mode, status.order_process_bar, now_s), now_s, out, made);
  return made;
}

}  // namespace cerebellum
