// A build without MuJoCo (CEREBELLUM_WITH_SIM=OFF, the robot's): the two-leg stand's design is
// refused with the reason, which TwoLegStandController keeps as its design error (mode 64 then
// stays on four feet and refuses its next starts naming it)
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "control/upright/upright_balance_design.hpp"

namespace cerebellum {
namespace {

TEST(UprightBalanceWithoutMuJoCo, TheDesignIsRefusedNamingTheModelAndTheBuildWithoutTheSimulator) {
  try {
    design_upright_balance("models/cyberdog2.xml", UprightDesignConfig{}, 0.002);
    FAIL() << "the design returned without MuJoCo";
  } catch (const std::runtime_error& error) {
    const std::string what = error.what();
    EXPECT_NE(what.find("models/cyberdog2.xml"), std::string::npos) << what;
    EXPECT_NE(what.find("CEREBELLUM_WITH_SIM=OFF"), std::string::npos) << what;
    EXPECT_NE(what.find("mode 64 is not available"), std::string::npos) << what;
  }
}

}  // namespace
}  // namespace cerebellum
