// An uploaded user-gait file: checked, stored, and handed to the loop once both halves are valid.
#include "motions/user_gait_upload.hpp"

#include <gtest/gtest.h>

#include <string>

namespace cerebellum {
namespace {

constexpr const char* kDefinition =
    "# Gait Def\n"
    "[[section]]\ncontact = [1, 1, 1, 1]\nduration = 10\n\n"
    "[[section]]\ncontact = [0, 1, 1, 0]\nduration = 4\n\n"
    "[[section]]\ncontact = [1, 0, 0, 1]\nduration = 4\n";

constexpr const char* kParameters =
    "# Gait Params\n"
    "[[step]]\nmode = 11\ngait_id = 110\nduration = 300\nvel_des = [0.1, 0.0, 0.0]\n"
    "step_height = [0.05, 0.05]\n"
    "[[step]]\nmode = 11\ngait_id = 110\nduration = 240\nvel_des = [0, 0, 0]\n";

TEST(UserGaitUpload, TheGaitReachesTheLoopOnlyOnceItsDefinitionAndParametersAreBothStored) {
  UserGaitSlot slot;
  UserGaitUpload upload(slot);
  const UserGaitUploadResult definition = upload.receive(kDefinition);
  EXPECT_TRUE(definition.accepted) << definition.detail;
  EXPECT_NE(definition.detail.find("waiting for the parameters"), std::string::npos) << definition.detail;
  EXPECT_EQ(slot.current(), nullptr);
  const UserGaitUploadResult parameters = upload.receive(kParameters);
  ASSERT_TRUE(parameters.accepted) << parameters.detail;
  EXPECT_NE(parameters.detail.find("ready to run"), std::string::npos) << parameters.detail;
  ASSERT_NE(slot.current(), nullptr);
  EXPECT_EQ(slot.current()->steps.size(), 2u);
  EXPECT_EQ(upload.store().version(), 2u);
}

TEST(UserGaitUpload, AnAcceptedParametersFileSaysTheWbcWeightsAndUseMpcTrajAreNotUsed) {
  UserGaitSlot slot;
  UserGaitUpload upload(slot);
  const UserGaitUploadResult parameters = upload.receive(kParameters);
  ASSERT_TRUE(parameters.accepted) << parameters.detail;
  EXPECT_NE(parameters.detail.find("acc_des (WBC weights) and value bit 0 (use_mpc_traj) not used"), std::string::npos)
      << parameters.detail;
  // a definition holds neither
  const UserGaitUploadResult definition = upload.receive(kDefinition);
  EXPECT_EQ(definition.detail.find("not used"), std::string::npos) << definition.detail;
}

TEST(UserGaitUpload, AFileThatDoesNotParseIsRefusedAndThePreviousGaitKept) {
  UserGaitSlot slot;
  UserGaitUpload upload(slot);
  ASSERT_TRUE(upload.receive(kDefinition).accepted);
  ASSERT_TRUE(upload.receive(kParameters).accepted);
  const std::shared_ptr<const UserGaitProgram> before = slot.current();
  const UserGaitUploadResult broken = upload.receive("# Gait Def\n[[section]]\ncontact = [1, 1\n");
  EXPECT_FALSE(broken.accepted);
  EXPECT_FALSE(broken.detail.empty());
  EXPECT_EQ(slot.current(), before);
  EXPECT_EQ(upload.store().version(), 2u);
}

TEST(UserGaitUpload, AnUnsafeDefinitionIsRefusedWithItsReason) {
  UserGaitSlot slot;
  UserGaitUpload upload(slot);
  // every foot in the air for 0.6 s: longer than any flight the robot can land
  const UserGaitUploadResult unsafe =
      upload.receive("# Gait Def\n[[section]]\ncontact = [0, 0, 0, 0]\nduration = 20\n\n"
                     "[[section]]\ncontact = [1, 1, 1, 1]\nduration = 10\n");
  EXPECT_FALSE(unsafe.accepted) << unsafe.detail;
  EXPECT_NE(unsafe.detail.find("the previous gait is kept"), std::string::npos) << unsafe.detail;
  EXPECT_FALSE(upload.store().definition().has_value());
}

}  // namespace
}  // namespace cerebellum
