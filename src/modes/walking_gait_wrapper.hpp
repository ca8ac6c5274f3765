// A gait that steers the walking gaits' controller itself (the passive trot, the stand with push
// recovery): it decides each tick which walking command to give, and hands the robot over
// mid-stride to and from the other gaits of that controller (LocomotionGait::take_over).
// Everything else it forwards to the walking gaits.
#pragma once

#include "modes/locomotion_gait.hpp"
#include "modes/walking_gaits.hpp"

namespace cerebellum {

class WalkingGaitWrapper : public LocomotionGait {
 public:
  explicit WalkingGaitWrapper(WalkingGaits& walking) : walking_(walking) {}

  const char* check(const HighLevelCommand& command) const override { return walking_.check(command); }
  ContactPlan contact_plan() const override { return walking_.contact_plan(); }
  const void* walking_controller() const override { return &walking_; }
  int progress_percent() const override { return 100; }
  bool damping_protection() const override { return walking_.failed(); }

 protected:
  WalkingGaits& walking_;
};

}  // namespace cerebellum
