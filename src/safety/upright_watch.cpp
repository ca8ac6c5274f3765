#include "safety/upright_watch.hpp"

#include <cmath>

namespace cerebellum {

bool upright_balance_lost(double tilt_error_rad, double offset_error_m, const UprightWatchLimits& limits) {
  // NaN (a broken state) counts as lost
  return !(tilt_error_rad < limits.tilt_error_rad) || !(offset_error_m < limits.offset_error_m);
}

}  // namespace cerebellum
