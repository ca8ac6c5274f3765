#include "cli/sim_options.hpp"

#include <gtest/gtest.h>

namespace cerebellum {
namespace {

std::string parse_error(const std::vector<std::string>& args) {
  try {
    parse_sim_options(args);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(SimOptions, ParsesEveryOption) {
  const SimOptions options =
      parse_sim_options({"--speed", "2.5", "--duration", "10", "--config", "a.yaml", "--seed", "7"});
  EXPECT_DOUBLE_EQ(options.speed, 2.5);
  EXPECT_DOUBLE_EQ(options.duration_s, 10.0);
  EXPECT_EQ(options.config_path, "a.yaml");
  EXPECT_EQ(options.seed.value(), 7u);
  EXPECT_FALSE(options.help);
}

TEST(SimOptions, TheTerrainOptionTakesASpecAndRefusesAWrongOneWithTheAcceptedForms) {
  const SimOptions options = parse_sim_options({"--terrain", "stairs:0.1:0.28"});
  ASSERT_TRUE(options.terrain.has_value());
  EXPECT_EQ(options.terrain->kind, TerrainKind::Stairs);
  EXPECT_FALSE(parse_sim_options({}).terrain.has_value());
  const std::string error = parse_error({"--terrain", "stairs:0.1"});
  EXPECT_NE(error.find("terrain 'stairs:0.1': 'stairs' takes 2 values"), std::string::npos) << error;
  EXPECT_NE(error.find("accepted: flat, slope:DEG"), std::string::npos) << error;
}

TEST(SimOptions, MaxSpeedMeansUnpaced) {
  EXPECT_LE(parse_sim_options({"--speed", "max"}).speed, 0.0);
  EXPECT_DOUBLE_EQ(parse_sim_options({}).speed, 1.0);
  EXPECT_LT(parse_sim_options({}).duration_s, 0.0);
}

TEST(SimOptions, BadValuesNameTheOptionAndTheAcceptedValues) {
  EXPECT_NE(parse_error({"--speed", "fast"}).find("--speed: 'fast' is not a number > 0 or 'max'"), std::string::npos);
  EXPECT_NE(parse_error({"--speed", "-1"}).find("must be > 0 or 'max'"), std::string::npos);
  EXPECT_NE(parse_error({"--duration", "0"}).find("--duration: must be > 0"), std::string::npos);
  EXPECT_NE(parse_error({"--duration", "inf"}).find("--duration"), std::string::npos);
  EXPECT_NE(parse_error({"--seed", "1.5"}).find("--seed: must be an integer"), std::string::npos);
  EXPECT_NE(parse_error({"--config"}).find("--config needs a value"), std::string::npos);
  EXPECT_NE(parse_error({"--fly"}).find("unknown option '--fly'"), std::string::npos);
}

}  // namespace
}  // namespace cerebellum
