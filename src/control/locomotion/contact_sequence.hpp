// A non-periodic contact schedule, played once: the sections of a user gait definition (each a
// stance pattern held for a number of MPC segments). Every leg's stance and swing runs are found
// once, when the sequence is built, so the control tick only looks them up. Before the first
// segment and after the last the robot stands (every leg in stance).
#pragma once

#include <array>
#include <vector>

#include "core/joint_layout.hpp"

namespace cerebellum {

class ContactSequence {
 public:
  struct Section {
    std::array<bool, kNumLegs> stance{};  // FR, FL, RR, RL
    int segments = 1;
  };
  // a run of one leg: consecutive segments all in stance or all in swing
  struct Run {
    int first = 0;   // segment
    int length = 1;  // segments; a stance run reaching the end counts the standing after it too
  };
  // a stance run that reaches the end of the sequence is this much longer (the stand after it)
  static constexpr int kStandAfterEndSegments = 10;

  // sections with segments < 1 are skipped
  explicit ContactSequence(const std::vector<Section>& sections);

  int segments() const { return static_cast<int>(stance_.size()); }
  // stance outside [0, segments())
  bool in_stance(std::size_t leg, int segment) const;
  // the run of the leg through the segment (0 <= segment < segments())
  Run run(std::size_t leg, int segment) const;

 private:
  std::vector<std::array<bool, kNumLegs>> stance_;
  std::vector<std::array<Run, kNumLegs>> runs_;
};

}  // namespace cerebellum
