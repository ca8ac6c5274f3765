#include "control/joint_ramp.hpp"

#include <algorithm>
#include <cmath>

#include "core/robot_model.hpp"

namespace cerebellum {

double smooth_step(double fraction) {
  const double s = std::clamp(fraction, 0.0, 1.0);
  return 0.5 - 0.5 * std::cos(robot::kPi * s);
}

JointArray<double> on_every_leg(const std::array<double, 3>& leg_pose) {
  JointArray<double> q{};
  for (std::size_t i = 0; i < kNumJoints; ++i) q[i] = leg_pose[i % kJointsPerLeg];
  return q;
}

void ramp_joints(const JointArray<double>& from, const JointArray<double>& to, double fraction, double kp, double kd,
                 JointCommand& command) {
  for (std::size_t i = 0; i < kNumJoints; ++i) {
    command.q_des[i] = from[i] + (to[i] - from[i]) * fraction;
    command.qd_des[i] = 0.0;
    command.kp[i] = kp;
    command.kd[i] = kd;
    command.tau_ff[i] = 0.0;
  }
}

}  // namespace cerebellum
