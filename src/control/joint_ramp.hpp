// The MC's joint-space move, in one unit: every joint from a start posture to a target along a
// smooth 0..1 ramp (zero slope at both ends), held by a joint PD. The stand-up, the self-righting
// keyframes, the lifted hold and the active lie-down all move the legs this way.
#pragma once

#include <array>

#include "core/joint_layout.hpp"
#include "core/types.hpp"

namespace cerebellum {

// smooth 0..1 ramp with zero slope at both ends (a half cosine); fraction is clamped to [0, 1]
double smooth_step(double fraction);

// one leg's pose (abad, hip, knee) on all four legs
JointArray<double> on_every_leg(const std::array<double, 3>& leg_pose);

// the joint targets `fraction` (already smoothed) of the way from `from` to `to`, with zero
// target velocity and feed-forward torque, held with kp and kd
void ramp_joints(const JointArray<double>& from, const JointArray<double>& to, double fraction, double kp, double kd,
                 JointCommand& command);

}  // namespace cerebellum
