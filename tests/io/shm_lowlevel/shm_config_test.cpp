// The `shm:` section of the configuration and the names it gives the objects.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <string>

#include "loop/mc_config.hpp"
#include "io/shm_lowlevel/shm_lowlevel_config.hpp"
#include "io/shm_lowlevel/shm_test_names.hpp"

namespace cerebellum {
namespace {

TEST(ShmConfig, ModeIsOctalWithOwnerReadWrite) {
  EXPECT_EQ(parse_shm_mode("0660"), 0660u);
  EXPECT_EQ(parse_shm_mode("660"), 0660u);
  EXPECT_EQ(parse_shm_mode("0666"), 0666u);
  EXPECT_EQ(parse_shm_mode("0600"), 0600u);
  EXPECT_EQ(parse_shm_mode("0400"), std::nullopt);  // the owner must be able to write
  EXPECT_EQ(parse_shm_mode("0860"), std::nullopt);  // not octal
  EXPECT_EQ(parse_shm_mode("1660"), std::nullopt);  // beyond permission bits
  EXPECT_EQ(parse_shm_mode("rw-rw----"), std::nullopt);
  EXPECT_EQ(parse_shm_mode(""), std::nullopt);
}

TEST(ShmConfig, PrefixMakesTheObjectNames) {
  EXPECT_EQ(shm_spline_object_name(""), "/spline_shm");
  EXPECT_EQ(shm_imu_object_name(""), "/imu_shm");
  EXPECT_EQ(shm_spline_object_name("dog2_"), "/dog2_spline_shm");
  EXPECT_EQ(shm_imu_object_name("dog2_"), "/dog2_imu_shm");
  EXPECT_TRUE(shm_name_prefix_problem("dog-2.test_").empty());
  EXPECT_FALSE(shm_name_prefix_problem("a/b").empty());
  EXPECT_FALSE(shm_name_prefix_problem("a b").empty());
  EXPECT_FALSE(shm_name_prefix_problem(std::string(65, 'x')).empty());
}

TEST(ShmConfig, DefaultsAreServedVendorNamesAndUserGroupOnly) {
  const ShmLowLevelConfig shm = default_config().shm;
  EXPECT_TRUE(shm.enabled);
  EXPECT_EQ(shm.name_prefix, "");
  EXPECT_EQ(shm.mode, 0660u);
  EXPECT_EQ(shm.command_timeout_cycles, 10);
}

class ShmConfigFile : public ::testing::Test {
 protected:
  std::string write(const std::string& text) {
    path_ = ::testing::TempDir() + unique_shm_prefix() + "config.yaml";
    std::ofstream(path_) << text;
    return path_;
  }
  void TearDown() override { std::remove(path_.c_str()); }
  std::string path_;
};

TEST_F(ShmConfigFile, SectionIsRead) {
  const McConfig config = load_config(write("shm:\n  enabled: false\n  name_prefix: dog2_\n  mode: 0640\n"));
  EXPECT_FALSE(config.shm.enabled);
  EXPECT_EQ(config.shm.name_prefix, "dog2_");
  EXPECT_EQ(config.shm.mode, 0640u);
}

TEST_F(ShmConfigFile, WorldWritableOnlyWhenAskedFor) {
  EXPECT_EQ(load_config(write("shm:\n  mode: \"0666\"\n")).shm.mode, 0666u);
}

void expect_error(const std::string& path, const std::string& fragment) {
  try {
    load_config(path);
    ADD_FAILURE() << "no ConfigError for " << path;
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
  }
}

TEST_F(ShmConfigFile, BadValuesNameTheKey) {
  expect_error(write("shm:\n  mode: 0999\n"), "shm.mode must be octal");
  expect_error(write("shm:\n  name_prefix: a/b\n"), "shm.name_prefix contains '/'");
  expect_error(write("shm:\n  enabled: maybe\n"), "shm.enabled must be true or false");
  expect_error(write("shm:\n  size: 10240\n"), "shm.size is not a known key");
  expect_error(write("shm:\n  group: no_such_group_here\n"),
               "shm.group is not a group of this system: 'no_such_group_here'");
}

TEST(ShmConfig, GroupsAreFoundByNameOrNumber) {
  EXPECT_EQ(find_group_id("root"), 0u);
  EXPECT_EQ(find_group_id("0"), 0u);
  EXPECT_EQ(find_group_id("no_such_group_here"), std::nullopt);
  EXPECT_EQ(find_group_id(""), std::nullopt);
  EXPECT_EQ(find_group_id("4294967"), std::nullopt);  // a number no group has
}

TEST_F(ShmConfigFile, TheGroupWhoMayWriteIsRead) {
  EXPECT_EQ(load_config(write("shm:\n  group: root\n")).shm.group_id, 0u);
  EXPECT_EQ(load_config(write("shm:\n  mode: 0660\n")).shm.group_id, std::nullopt);
}

}  // namespace
}  // namespace cerebellum
