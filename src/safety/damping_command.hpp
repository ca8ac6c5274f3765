// Joint damping, the command every protective stop falls back to: kp 0, qd_des 0, tau_ff 0 and
// kd on every joint, so the motors brake the joints and the robot sinks down slowly.
#pragma once

#include "core/types.hpp"

namespace cerebellum {

// q_des has no effect without kp; callers that report the command set it to the measured angles
JointCommand damping_command(double kd, const JointArray<double>& q_des = {});

}  // namespace cerebellum
