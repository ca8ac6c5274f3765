// When a robot balancing on its hind feet (mode 64) has gone past what its balance can catch: the
// trunk tilted or the body moved off the feet too far from the reference. Then the mode damps the
// joints (EDAMP) and the recovery stand follows, as after any fall.
#pragma once

namespace cerebellum {

struct UprightWatchLimits {
  double tilt_error_rad = 0.6;   // the trunk from its reference, about the world's horizontal axes
  double offset_error_m = 0.12;  // the trunk from its reference relative to the hind feet
};

bool upright_balance_lost(double tilt_error_rad, double offset_error_m, const UprightWatchLimits& limits = {});

}  // namespace cerebellum
