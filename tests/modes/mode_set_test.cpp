// The one assembly of the modes and gaits (the MC's and the simulation tests'): which controller
// serves each gait id of mode 11.
#include <gtest/gtest.h>

#include "modes/mode_set.hpp"

namespace cerebellum {
namespace {

constexpr int kWalkingGaitIds[] = {2, 3, 7, 10, 26, 27};  // docs/locomotion.md
constexpr int kStandGaitIds[] = {1, 31};
constexpr int kPassiveTrotGaitIds[] = {4};

ModeSetConfig config_with(LocomotionStand stand) {
  ModeSetConfig config;
  config.locomotion_stand = stand;
  return config;
}

TEST(ModeSet, WalkingGaitsRunOnTheMpcTheStandsOnTheConfiguredControllerAndGaitFourOnThePassiveTrot) {
  for (LocomotionStand stand : {LocomotionStand::Mpc, LocomotionStand::Qp}) {
    const ModeSet modes(config_with(stand));
    for (int id : kWalkingGaitIds) EXPECT_EQ(modes.gaits().find(id), &modes.walking()) << id;
    // on the MPC, gait 1 is the stand that steps to recover from a push; 31 the plain one
    const bool mpc = stand == LocomotionStand::Mpc;
    EXPECT_EQ(modes.gaits().find(kStandGaitId),
              mpc ? static_cast<const LocomotionGait*>(&modes.push_recovery_stand()) : &modes.qp_stand_gait());
    EXPECT_EQ(modes.gaits().find(kStandWithoutPushRecoveryGaitId),
              mpc ? static_cast<const LocomotionGait*>(&modes.walking()) : &modes.qp_stand_gait());
    // the push recovery drives the walking controller itself
    EXPECT_EQ(modes.push_recovery_stand().walking_controller(), &modes.walking());
    // the passive trot drives the walking controller itself, whichever stand is configured
    for (int id : kPassiveTrotGaitIds) EXPECT_EQ(modes.gaits().find(id), &modes.passive_trot()) << id;
  }
}

TEST(ModeSet, TheUploadedUserGaitRunsOnItsOwnRunner) {
  ModeSet modes(ModeSetConfig{});
  EXPECT_EQ(modes.gaits().find(kUserGaitId), &modes.user_gait());
}

TEST(ModeSet, OtherGaitIdsHaveNoController) {
  const ModeSet modes(ModeSetConfig{});
  for (int id = 0; id <= GaitRegistry::kMaxGaitId; ++id) {
    bool listed = false;
    for (int walking : kWalkingGaitIds) listed |= walking == id;
    for (int stand : kStandGaitIds) listed |= stand == id;
    for (int passive : kPassiveTrotGaitIds) listed |= passive == id;
    listed |= id == kUserGaitId;
    if (!listed) {
      EXPECT_EQ(modes.gaits().find(id), nullptr) << id;
    }
  }
}

}  // namespace
}  // namespace cerebellum
