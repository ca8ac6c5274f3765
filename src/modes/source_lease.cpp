#include "modes/source_lease.hpp"

namespace cerebellum {

SourceLease::Verdict SourceLease::judge(HighLevelSource source, double received_s) {
  if (holder_ == source) {
    holder_last_s_ = received_s;
    return Verdict::Holds;
  }
  if (holder_ && received_s - holder_last_s_ <= silence_timeout_s_) return Verdict::Refused;
  const bool first = !holder_;
  holder_ = source;
  holder_last_s_ = received_s;
  return first ? Verdict::Holds : Verdict::TakesOver;
}

}  // namespace cerebellum
