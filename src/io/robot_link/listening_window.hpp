// The span over which a receiving thread has been listening without a pause of its own, so that a
// link watch judges only silence the receiver could have heard. A receiver that was not running
// (descheduled, or the whole machine stalled, as a virtual machine's host does for tens of
// milliseconds) cannot tell a silent robot from its own absence; and a reader on another thread
// must not judge "now" before the receiver has had its turn after such a stall, so the silence
// ends at the receiver's last step (until_s), never at the reader's clock.
#pragma once

#include <atomic>

namespace cerebellum {

struct ListeningWindow {
  double since_s = 0.0;  // the receiver listens without a pause since then
  double until_s = 0.0;  // its newest step: what came before this has been taken
};

// The receiver's thread calls step(now) each time it is about to take its messages; any thread
// may read window(). Two atomics, not a lock: the writer stores since before until (release), the
// reader loads until before since (acquire), so a reader that sees a new until sees its since too;
// the only mixed read (an old until with a new since) gives since > until, no silence at all, which
// errs towards a healthy link for one reading only.
class ListeningClock {
 public:
  // pause_s: a gap between two steps longer than this is a pause of the receiver's own
  explicit ListeningClock(double pause_s) : pause_s_(pause_s) {}

  void step(double now_s) {
    if (now_s - until_s_.load(std::memory_order_relaxed) > pause_s_) {
      since_s_.store(now_s, std::memory_order_release);
    }
    until_s_.store(now_s, std::memory_order_release);
  }

  ListeningWindow window() const {
    ListeningWindow window;
    window.until_s = until_s_.load(std::memory_order_acquire);
    window.since_s = since_s_.load(std::memory_order_acquire);
    return window;
  }

 private:
  double pause_s_;
  std::atomic<double> since_s_{0.0};
  std::atomic<double> until_s_{0.0};
};

}  // namespace cerebellum
