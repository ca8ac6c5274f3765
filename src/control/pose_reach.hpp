// Whether the legs can hold a body pose over their footholds, and how far towards a pose they can
// go: a pose beyond reach is cut back along the way to it rather than driving the knees into
// their stops.
#pragma once

#include <array>

#include <Eigen/Core>

#include "control/stance_frame.hpp"

namespace cerebellum {

using Footholds = std::array<Eigen::Vector3d, kNumLegs>;

// every foot in `feet` can be placed on its foothold with the joints inside their ranges (less
// margin_rad) from this body pose (stance frame)
bool feet_reachable(const BodyPose& pose, const Footholds& footholds, const LegMask& feet, double margin_rad = 0.05);

// the largest fraction s in [0, 1] such that the pose from + s (to - from) keeps the feet
// reachable (found by bisection to 1e-3); 0 when even `from` is out of reach
double reachable_fraction(const BodyPose& from, const BodyPose& to, const Footholds& footholds, const LegMask& feet,
                          double margin_rad = 0.05);

// from + fraction (to - from)
BodyPose blend(const BodyPose& from, const BodyPose& to, double fraction);

}  // namespace cerebellum
