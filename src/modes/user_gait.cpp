#include "modes/user_gait.hpp"

#include <algorithm>

#include "control/locomotion/gait_table.hpp"

namespace cerebellum {

Eigen::Vector3d UserGaitStep::body_velocity() const {
  Eigen::Vector3d body = velocity;
  if (duration_s > 0.0) body.head<2>() += position_offset_m / duration_s;
  return body;
}

double UserGaitProgram::sequence_s() const { return sequence ? sequence->segments() * kGaitSegmentS : 0.0; }

double UserGaitProgram::steps_s() const {
  double total = 0.0;
  for (const UserGaitStep& step : steps) total += step.duration_s;
  return total;
}

double UserGaitProgram::duration_s() const { return std::max(sequence_s(), steps_s()); }

}  // namespace cerebellum
