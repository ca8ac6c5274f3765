// The AlienGo client in the tick. Its transport (the UDP adapter's thread) only decodes HighCmds
// and hands them over through its AlienGoInbox; each tick the client's sport session
// (AlienGoSession: the vendor's mode table, the mode-3 position controller, the silence timers)
// turns what arrived, or the silence, into the MC's own high-level commands on the tick's state,
// and the stage reports the mode HighState shows.
#pragma once

#include "modes/aliengo_inbox.hpp"
#include "modes/aliengo_session.hpp"
#include "modes/source_stage.hpp"

namespace cerebellum {

class AlienGoSource final : public SourceStage {
 public:
  explicit AlienGoSource(const AlienGoSessionConfig& config = {});

  // what the transport is given (before the loop starts)
  AlienGoInbox& inbox() { return inbox_; }
  // the transport's thread (one thread): a decoded HighCmd; false when the ring is full or
  // another thread already hands over
  bool push(const AlienGoCommand& command) { return inbox_.push(command); }

  // loop thread
  std::size_t step(const RobotState& state, const HighLevelStatus& status, Commands& out) override;
  void report(HighLevelReport& report) const override {
    report.aliengo_mode = reported_mode_;
    report.aliengo_frame = session_.frame();
  }
  // loop thread (tests, the stage itself): the client's session
  const AlienGoSession& session() const { return session_; }

  // any thread
  const AlienGoInboxCounters& counters() const { return inbox_.counters(); }

 private:
  void submit(const AlienGoStep& step, double now_s, Commands& out, std::size_t& made);

  AlienGoInbox inbox_;
  // loop thread
  AlienGoSession session_;
  int reported_mode_ = 0;
  int pending_mode_ = 0;
  int pending_mc_mode_ = -1;
  int pending_mc_gait_ = -1;
};

}  // namespace cerebellum
