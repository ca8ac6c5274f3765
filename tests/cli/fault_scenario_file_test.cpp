// Fault scenario files: entries in the fault grammar at simulated times; every mistake names the
// file, the entry and what is accepted.
#include "cli/fault_scenario_file.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace cerebellum {
namespace {

std::string error_of(const std::string& text) {
  try {
    parse_fault_scenario(text, "s.yaml");
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "no error";
}

TEST(FaultScenarioFile, EntriesBecomeTimedFaults) {
  const std::vector<TimedFault> scenario = parse_fault_scenario(
      "faults:\n"
      "  - at_s: 5\n"
      "    fault: motor FR_knee disconnected\n"
      "    duration_s: 4\n"
      "  - at_s: 12.5\n"
      "    fault: battery soc 4\n"
      "  - {at_s: 20, fault: clear}\n",
      "s.yaml");
  ASSERT_EQ(scenario.size(), 3u);
  EXPECT_EQ(scenario[0].at_s, 5.0);
  EXPECT_EQ(scenario[0].request.index, 2);
  EXPECT_EQ(scenario[0].request.duration_s, 4.0);
  EXPECT_EQ(scenario[1].request.kind, FaultKind::BatteryStateOfCharge);
  EXPECT_EQ(scenario[1].request.value, 4.0);
  EXPECT_EQ(scenario[2].request.kind, FaultKind::Clear);
  EXPECT_TRUE(parse_fault_scenario("", "empty.yaml").empty());
}

TEST(FaultScenarioFile, MistakesNameTheEntryAndWhatIsAccepted) {
  EXPECT_EQ(error_of("faults: [\n"), error_of("faults: [\n"));  // deterministic
  EXPECT_NE(error_of("faults: [\n").find("fault scenario s.yaml: not valid YAML"), std::string::npos);
  EXPECT_NE(error_of("fault:\n  - at_s: 1\n").find("<top>.fault is not a known key (accepted: faults)"),
            std::string::npos);
  EXPECT_NE(error_of("faults: 3\n").find("faults must be a list"), std::string::npos);
  EXPECT_NE(error_of("faults:\n  - fault: imu stuck\n").find("faults[0] needs at_s"), std::string::npos);
  EXPECT_NE(error_of("faults:\n  - at_s: 1\n").find("faults[0] needs fault"), std::string::npos);
  EXPECT_NE(error_of("faults:\n  - {at_s: -1, fault: imu stuck}\n").find("faults[0].at_s must be in [0, 86400]"),
            std::string::npos);
  EXPECT_NE(error_of("faults:\n  - {at_s: 1, fault: imu stuck}\n  - {at_s: 2, fault: motor 13 stuck}\n")
                .find("faults[1].fault motor must be 0..11"),
            std::string::npos);
  EXPECT_NE(error_of("faults:\n  - {at_s: 1, fault: imu stuck, at_s: 2}\n").find("faults[0].at_s appears twice"),
            std::string::npos);
  EXPECT_NE(error_of("faults:\n  - {at_s: 1, fault: clear, duration_s: 2}\n").find("is not taken by a clear"),
            std::string::npos);
  EXPECT_NE(error_of("faults:\n  - {at_s: 1, fault: imu stuck, when: now}\n")
                .find("faults[0].when is not a known key (accepted: at_s, duration_s, fault)"),
            std::string::npos);
}

TEST(FaultScenarioFile, AFolderOrAMissingOrOversizedFileIsRefusedByName) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "cerebellum_fault_scenario_test";
  std::filesystem::create_directories(dir);
  EXPECT_THROW(load_fault_scenario(dir.string()), ConfigError);
  EXPECT_THROW(load_fault_scenario((dir / "missing.yaml").string()), ConfigError);
  const std::filesystem::path big = dir / "big.yaml";
  std::ofstream(big) << std::string(kFaultScenarioMaxBytes + 1, '#');
  try {
    load_fault_scenario(big.string());
    ADD_FAILURE() << "an oversized file was read";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("more than the limit"), std::string::npos) << e.what();
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace cerebellum
