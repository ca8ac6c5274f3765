#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <string>

#include "loop/mc_config.hpp"
#include "io/lcm_highlevel/lcm_highlevel_config.hpp"

namespace cerebellum {
namespace {

TEST(LcmUrl, TheInterfaceUrlsAndVariantsAreAccepted) {
  const HighLevelLcmConfig defaults;
  for (const std::string& url :
       {defaults.command_url, defaults.response_url, defaults.odometry_url, std::string("udpm://239.255.76.67:7671"),
        std::string("udpm://224.0.0.251:1?ttl=0"), std::string("udpm://239.1.2.3:65535?recv_buf_size=4096&ttl=1")}) {
    EXPECT_EQ(lcm_url_problem(url), "") << url;
  }
}

TEST(LcmUrl, ProblemsAreNamed) {
  EXPECT_EQ(lcm_url_problem("tcpq://127.0.0.1:7700"), "must start with udpm://");
  EXPECT_EQ(lcm_url_problem("udpm://239.255.76.67"), "needs <group>:<port> after udpm://");
  EXPECT_EQ(lcm_url_problem("udpm://192.168.1.2:7671"), "'192.168.1.2' is not a multicast group (224..239.x.x.x)");
  EXPECT_EQ(lcm_url_problem("udpm://239.255.76:7671"), "'239.255.76' is not an IPv4 address");
  EXPECT_EQ(lcm_url_problem("udpm://239.255.76.256:7671"), "'239.255.76.256' is not an IPv4 address");
  EXPECT_EQ(lcm_url_problem("udpm://239.255.76.67:0"), "port must be an integer in [1, 65535]");
  EXPECT_EQ(lcm_url_problem("udpm://239.255.76.67:76711"), "port must be an integer in [1, 65535]");
  EXPECT_EQ(lcm_url_problem("udpm://239.255.76.67:7671?ttl=256"), "ttl must be an integer in [0, 255]");
  EXPECT_EQ(lcm_url_problem("udpm://239.255.76.67:7671?ttl"), "option 'ttl' is not key=value");
}

class HighLevelConfigFile : public ::testing::Test {
 protected:
  std::string write(const std::string& text) {
    // one file per test process: ctest runs this suite's tests side by side
    const std::string path = ::testing::TempDir() + "highlevel_config_test_" + std::to_string(::getpid()) + ".yaml";
    std::ofstream(path) << text;
    return path;
  }
  std::string error_of(const std::string& text) {
    try {
      load_config(write(text));
    } catch (const ConfigError& e) {
      return e.what();
    }
    return "";
  }
};

TEST_F(HighLevelConfigFile, DefaultsServeTheInterfaceUrlsOnThisHostOnly) {
  const McConfig config = default_config();
  EXPECT_TRUE(config.highlevel.enabled);
  EXPECT_EQ(config.highlevel.command_url, "udpm://239.255.76.67:7671?ttl=0");
  EXPECT_EQ(config.highlevel.response_url, "udpm://239.255.76.67:7670?ttl=0");
  EXPECT_EQ(config.highlevel.odometry_url, "udpm://239.255.76.67:7667?ttl=0");
  EXPECT_DOUBLE_EQ(config.highlevel.response_keepalive_s, 0.1);
}

TEST_F(HighLevelConfigFile, EveryKeyIsRead) {
  const McConfig config = load_config(
      write("highlevel:\n  enabled: false\n  command_url: udpm://239.255.76.67:7671?ttl=255\n"
            "  response_url: udpm://239.255.76.67:7670?ttl=255\n  odometry_url: udpm://239.255.76.67:7667?ttl=255\n"
            "  response_keepalive_s: 0\n"));
  EXPECT_FALSE(config.highlevel.enabled);
  EXPECT_EQ(config.highlevel.command_url, "udpm://239.255.76.67:7671?ttl=255");
  EXPECT_EQ(config.highlevel.response_url, "udpm://239.255.76.67:7670?ttl=255");
  EXPECT_EQ(config.highlevel.odometry_url, "udpm://239.255.76.67:7667?ttl=255");
  EXPECT_DOUBLE_EQ(config.highlevel.response_keepalive_s, 0.0);
}

TEST_F(HighLevelConfigFile, BadValuesNameTheKey) {
  EXPECT_NE(error_of("highlevel:\n  enable: true\n").find("highlevel.enable is not a known key"), std::string::npos);
  EXPECT_NE(error_of("highlevel:\n  enabled: maybe\n").find("highlevel.enabled must be true or false"),
            std::string::npos);
  EXPECT_NE(error_of("highlevel:\n  response_url: udpm://10.0.0.1:7670\n")
                .find("highlevel.response_url '10.0.0.1' is not a multicast group"),
            std::string::npos);
  EXPECT_NE(
      error_of("highlevel:\n  response_keepalive_s: 0.5\n").find("highlevel.response_keepalive_s must be in [0, 0.19]"),
      std::string::npos);
}

}  // namespace
}  // namespace cerebellum
