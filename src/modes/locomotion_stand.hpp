// Which controller serves mode 11's stand gaits: a configuration choice of the MC.
#pragma once

namespace cerebellum {

// what serves mode 11's stand gaits 1 and 31
enum class LocomotionStand {
  Mpc,  // the walking controller with an all-stance schedule: a stand asked for while walking
        // first brings the body to rest by stepping
  Qp,   // the force-based QP stand of mode 3: gait 1 pulls the body back over its feet after a
        // push, 31 only damps it; a stand asked for while walking stops the legs at once
};

}  // namespace cerebellum
