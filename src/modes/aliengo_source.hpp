// The AlienGo client in the tick. Its transport (the UDP adapter's thread) only decodes HighCmds
// and hands them over through a single-producer ring; each tick the client's sport session
// (AlienGoSession: the vendor's mode table, the mode-3 position controller, the silence timers)
// turns what arrived, or the silence, into the MC's own high-level commands on the tick's state,
// and the stage reports the mode HighState shows.
#pragma once

#include <atomic>
#include <cstdint>

#include "core/claimed_ring.hpp"
#include "core/spsc_ring.hpp"
#include "modes/aliengo_session.hpp"
#include "modes/source_stage.hpp"

namespace cerebellum {

// a HighCmd the session refused (it stays in its mode), for the adapter's thread to log
struct AlienGoRefusal {
  int mode = 0;                  // what the client asked
  int session_mode = 0;          // where the session stays
  const char* reason = nullptr;  // a static string
};

// the ring's (HighCmds handed over, dropped for arriving faster than the tick takes them, refused
// from a second thread) and the session's
struct AlienGoSourceCounters : ClaimedRingCounters {
  std::atomic<std::uint64_t> illegal_moves{0};  // refused by the vendor's mode table
};

class AlienGoSource final : public SourceStage {
 public:
  static constexpr std::size_t kRingCapacity = 64;

  explicit AlienGoSource(const AlienGoSessionConfig& config = {});

  // the transport's thread (one thread): a decoded HighCmd; false when the ring is full or
  // another thread already hands over
  bool push(const AlienGoCommand& command) { return ring_.push(command); }

  // loop thread
  std::size_t step(const RobotState& state, const HighLevelStatus& status, Commands& out) override;
  void report(HighLevelReport& report) const override { report.aliengo_mode = reported_mode_; }
  // loop thread (tests, the stage itself): the client's session
  const AlienGoSession& session() const { return session_; }

  // any thread
  const AlienGoSourceCounters& counters() const { return ring_.counters(); }
  // the loop thread pushes, one consumer thread (the adapter's) pops
  SpscRing<AlienGoRefusal, 16>& refusals() { return refusals_; }

 private:
  void submit(const AlienGoStep& step, double now_s, Commands& out, std::size_t& made);

  ClaimedRing<AlienGoCommand, kRingCapacity, AlienGoSourceCounters> ring_;
  SpscRing<AlienGoRefusal, 16> refusals_;
  // loop thread
  AlienGoSession session_;
  int reported_mode_ = 0;
  int pending_mode_ = 0;
  int pending_mc_mode_ = -1;
  int pending_mc_gait_ = -1;
};

}  // namespace cerebellum
