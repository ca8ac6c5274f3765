#include "control/locomotion/contact_sequence.hpp"

namespace cerebellum {

ContactSequence::ContactSequence(const std::vector<Section>& sections) {
  for (const Section& section : sections) {
    for (int k = 0; k < section.segments; ++k) stance_.push_back(section.stance);
  }
  runs_.resize(stance_.size());
  const int n = segments();
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
    int first = 0;
    for (int k = 1; k <= n; ++k) {
      if (k < n && stance_[k][leg] == stance_[first][leg]) continue;
      Run run{first, k - first};
      // the standing before the first segment and after the last belongs to the stance runs there
      if (k == n && stance_[first][leg]) run.length += kStandAfterEndSegments;
      for (int s = first; s < k; ++s) runs_[s][leg] = run;
      first = k;
    }
  }
}

bool ContactSequence::in_stance(std::size_t leg, int segment) const {
  if (segment < 0 || segment >= segments()) return true;
  return stance_[static_cast<std::size_t>(segment)][leg];
}

ContactSequence::Run ContactSequence::run(std::size_t leg, int segment) const {
  return runs_[static_cast<std::size_t>(segment)][leg];
}

}  // namespace cerebellum
