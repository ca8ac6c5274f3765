// A build without MuJoCo (CEREBELLUM_WITH_SIM=OFF, e.g. the robot's aarch64 build) has no model
// dynamics to design the two-leg stand's balance on: the design fails with the reason, so mode 64
// keeps the robot on four feet and refuses its next starts naming it (TwoLegStandController).
#include <stdexcept>

#include "control/upright/upright_balance_design.hpp"

namespace cerebellum {

std::vector<UprightSample> design_upright_balance(const std::string& model_path, const UprightDesignConfig&,
                                                  double) {
  throw std::runtime_error("the two-leg stand's balance is designed on the MuJoCo model " + model_path +
                           ", and this build has no MuJoCo (CEREBELLUM_WITH_SIM=OFF): mode 64 is not available");
}

}  // namespace cerebellum
