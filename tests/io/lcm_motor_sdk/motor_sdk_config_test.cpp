// The user parameter file and the `motor_sdk:` config section: values, defaults, clear errors.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "loop/mc_config.hpp"
#include "lowlevel/motor_sdk/motor_sdk_user_parameters.hpp"

namespace cerebellum {
namespace {

namespace fs = std::filesystem;

class MotorSdkConfigFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("motor_sdk_config_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string write(const std::string& name, const std::string& text) const {
    const fs::path path = dir_ / name;
    std::ofstream(path) << text;
    return path.string();
  }

  fs::path dir_;
};

TEST_F(MotorSdkConfigFiles, UserParameterZeroSwitchesTheJumpClampOff) {
  const std::string path = write("user.yaml", "other_key: 3.5\nmotor_sdk_position_mutation_limit: 0\n");
  EXPECT_FALSE(load_motor_sdk_user_parameters(path).position_mutation_limit);
  write("user.yaml", "motor_sdk_position_mutation_limit: 1\n");
  EXPECT_TRUE(load_motor_sdk_user_parameters(path).position_mutation_limit);
}

TEST_F(MotorSdkConfigFiles, UserParameterDefaultsToOnWhenAbsent) {
  EXPECT_TRUE(load_motor_sdk_user_parameters(write("user.yaml", "other_key: 1\n")).position_mutation_limit);
  EXPECT_TRUE(load_motor_sdk_user_parameters(write("empty.yaml", "")).position_mutation_limit);
}

TEST_F(MotorSdkConfigFiles, UserParameterRejectsOtherValuesNamingTheKey) {
  const std::string path = write("user.yaml", "motor_sdk_position_mutation_limit: 2\n");
  try {
    load_motor_sdk_user_parameters(path);
    FAIL() << "accepted 2";
  } catch (const UserParameterError& e) {
    EXPECT_NE(std::string(e.what()).find("motor_sdk_position_mutation_limit must be 0 or 1, got '2'"),
              std::string::npos)
        << e.what();
  }
  EXPECT_THROW(load_motor_sdk_user_parameters((dir_ / "missing.yaml").string()), UserParameterError);
}

TEST_F(MotorSdkConfigFiles, ConfigSectionIsReadWithTheUserFileRelativeToIt) {
  write("user.yaml", "motor_sdk_position_mutation_limit: 0\n");
  const std::string config_path = write("mc.yaml",
                                        "mc:\n  startup: damper\n"
                                        "motor_sdk:\n  enabled: false\n"
                                        "  control_url: udpm://239.255.76.67:7667?ttl=255\n"
                                        "  estimator_url: udpm://239.255.76.67:7669?ttl=255\n"
                                        "  user_parameter_file: user.yaml\n");
  const McConfig config = load_config(config_path);
  EXPECT_FALSE(config.motor_sdk.enabled);
  EXPECT_EQ(config.motor_sdk.control_url, "udpm://239.255.76.67:7667?ttl=255");
  EXPECT_EQ(config.motor_sdk.estimator_url, "udpm://239.255.76.67:7669?ttl=255");
  EXPECT_EQ(fs::path(config.motor_sdk.user_parameter_file), dir_ / "user.yaml");
  EXPECT_FALSE(config.motor_sdk.parameters.position_mutation_limit);
}

TEST_F(MotorSdkConfigFiles, DefaultsServeTheVendorUrlsOnThisHostOnly) {
  const McConfig config = default_config();
  EXPECT_TRUE(config.motor_sdk.enabled);
  EXPECT_EQ(config.motor_sdk.control_url, "udpm://239.255.76.67:7667?ttl=0");
  EXPECT_EQ(config.motor_sdk.estimator_url, "udpm://239.255.76.67:7669?ttl=0");
  EXPECT_TRUE(config.motor_sdk.parameters.position_mutation_limit);
}

TEST_F(MotorSdkConfigFiles, BadValuesAreConfigErrorsNamingTheKey) {
  const auto error_of = [&](const std::string& text) -> std::string {
    try {
      load_config(write("bad.yaml", text));
    } catch (const ConfigError& e) {
      return e.what();
    }
    return "";
  };
  EXPECT_NE(error_of("motor_sdk:\n  enabled: maybe\n").find("motor_sdk.enabled must be true or false"),
            std::string::npos);
  EXPECT_NE(error_of("motor_sdk:\n  control_url: 239.255.76.67\n").find("motor_sdk.control_url must be an LCM url"),
            std::string::npos);
  EXPECT_NE(error_of("motor_sdk:\n  port: 7667\n").find("motor_sdk.port is not a known key"), std::string::npos);
  EXPECT_NE(error_of("motor_sdk:\n  user_parameter_file: nowhere.yaml\n").find("motor_sdk.user_parameter_file"),
            std::string::npos);
}

}  // namespace
}  // namespace cerebellum
