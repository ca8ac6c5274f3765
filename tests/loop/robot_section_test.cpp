// The configuration's robot: section: which robot the MC drives and its settings, with a precise
// error naming the key and the file for every mistake, and what a real robot cannot have refused.
#include "loop/mc_config.hpp"

#include <gtest/gtest.h>

#include <sys/stat.h>
#include <unistd.h>

#include <fstream>
#include <string>

namespace cerebellum {
namespace {

// in a folder of this process: ctest runs the cases of this file in parallel processes
std::string write_file(const std::string& text) {
  const std::string dir = ::testing::TempDir() + "robot_section_test_" + std::to_string(::getpid());
  ::mkdir(dir.c_str(), 0700);
  const std::string path = dir + "/robot.yaml";
  std::ofstream(path) << text;
  return path;
}

// the error of loading text (it must name the file), or "" when it loads
std::string load_error(const std::string& text) {
  const std::string path = write_file(text);
  try {
    load_config(path);
  } catch (const ConfigError& e) {
    const std::string error = e.what();
    EXPECT_NE(error.find(path), std::string::npos) << "the error names the file: " << error;
    return error;
  }
  return "";
}

// a motor SDK robot, its link given by link (YAML flow entries), its served interfaces off the
// robot's link ports; extra: more sections
std::string motor_sdk_robot(const std::string& link = "", const std::string& extra = "") {
  return "robot:\n  kind: cyberdog2_motor_sdk\n  cyberdog2_motor_sdk: {" + link +
         "}\n"
         "highlevel: {odometry_url: 'udpm://239.255.76.67:7672?ttl=0'}\n"
         "motor_sdk: {enabled: false, control_url: 'udpm://239.255.76.67:7767?ttl=0',"
         " estimator_url: 'udpm://239.255.76.67:7769?ttl=0'}\n" +
         extra;
}

TEST(RobotSection, TheRobotIsTheSimulationUnlessTheFileNamesAnother) {
  EXPECT_EQ(default_config().robot_kind, RobotKind::Sim);
  EXPECT_EQ(load_config(write_file("robot: {kind: sim, seed: 3}\n")).robot_kind, RobotKind::Sim);
}

TEST(RobotSection, AMotorSdkRobotTakesItsLinkSettingsAndDefaultsToTheVendorsTimings) {
  const McConfig defaults = load_config(write_file(motor_sdk_robot()));
  EXPECT_EQ(defaults.robot_kind, RobotKind::Cyberdog2MotorSdk);
  EXPECT_DOUBLE_EQ(defaults.motor_sdk_robot.link_timeout_s, 0.020);
  EXPECT_NE(defaults.motor_sdk_robot.control_url.find("ttl=0"), std::string::npos) << "this host only by default";
  EXPECT_TRUE(defaults.motor_sdk_robot.rules.position_mutation_limit) << "the vendor's 8 / 10 / 12 degree clamp";
  const McConfig config = load_config(write_file(motor_sdk_robot(
      "control_url: 'udpm://239.255.76.67:7667?ttl=255', link_timeout_s: 0.05, position_jump_limit: false")));
  EXPECT_EQ(config.motor_sdk_robot.control_url, "udpm://239.255.76.67:7667?ttl=255");
  EXPECT_DOUBLE_EQ(config.motor_sdk_robot.link_timeout_s, 0.05);
  EXPECT_FALSE(config.motor_sdk_robot.rules.position_mutation_limit);
}

TEST(RobotSection, AnUnknownKindIsRefusedWithTheAcceptedOnes) {
  const std::string error = load_error("robot: {kind: spot}\n");
  EXPECT_NE(error.find("robot.kind must be one of: cyberdog2_motor_sdk, sim, zsibot_shm; got 'spot'"),
            std::string::npos)
      << error;
}

TEST(RobotSection, AZsibotRobotTakesItsDaemonsNamePrefixAndDefaultsToTheVendorsNames) {
  const McConfig vendor = load_config(write_file("robot: {kind: zsibot_shm}\nshm: {enabled: false}\n"));
  EXPECT_EQ(vendor.robot_kind, RobotKind::ZsibotShm);
  EXPECT_EQ(vendor.shm_robot.name_prefix, "") << "the vendor's /spline_shm and /imu_shm";
  EXPECT_DOUBLE_EQ(vendor.shm_robot.link_timeout_s, 0.020);
  const McConfig stacked = load_config(write_file(
      "robot: {kind: zsibot_shm, zsibot_shm: {name_prefix: stack_, link_timeout_s: 0.01, activation_timeout_s: 5,"
      " motor_error_damping_kd: 2}}\n"));
  EXPECT_EQ(stacked.shm_robot.name_prefix, "stack_");
  EXPECT_DOUBLE_EQ(stacked.shm_robot.link_timeout_s, 0.01);
  EXPECT_DOUBLE_EQ(stacked.shm_robot.activation_timeout_s, 5.0);
  EXPECT_DOUBLE_EQ(stacked.shm_robot.motor_error_damping_kd, 2.0);
  EXPECT_EQ(stacked.sim_truth.rate_hz, 0.0) << "no simulator truth on a real robot";
}

TEST(RobotSection, EveryZsibotSettingIsCheckedByName) {
  const auto shm_error = [](const std::string& entry) {
    return load_error("robot: {kind: zsibot_shm, zsibot_shm: {" + entry + "}}\nshm: {enabled: false}\n");
  };
  std::string error = shm_error("name_prefix: '../etc'");
  EXPECT_NE(error.find("robot.zsibot_shm.name_prefix"), std::string::npos) << error;
  EXPECT_NE(error.find("got '../etc'"), std::string::npos) << error;
  error = shm_error("link_timeout_s: 0.001");
  EXPECT_NE(error.find("robot.zsibot_shm.link_timeout_s must be in [0.003, 0.5], got 0.001"), std::string::npos)
      << error;
  error = shm_error("prefix: a");
  EXPECT_NE(error.find("robot.zsibot_shm.prefix is not a known key"), std::string::npos) << error;
}

TEST(RobotSection, EachRobotsSubsectionIsRefusedWithAnotherKind) {
  std::string error = load_error("robot: {kind: cyberdog2_motor_sdk, zsibot_shm: {name_prefix: a}}\n");
  EXPECT_NE(error.find("robot.zsibot_shm applies only to robot.kind zsibot_shm (robot.kind is cyberdog2_motor_sdk)"),
            std::string::npos)
      << error;
  error = load_error("robot: {kind: zsibot_shm, cyberdog2_motor_sdk: {link_timeout_s: 0.02}}\n");
  EXPECT_NE(error.find("robot.cyberdog2_motor_sdk applies only to robot.kind cyberdog2_motor_sdk"), std::string::npos)
      << error;
}

TEST(RobotSection, AZsibotMcDoesNotServeTheSharedMemoryItReadsFromItsDaemon) {
  const std::string error = load_error("robot: {kind: zsibot_shm, zsibot_shm: {name_prefix: a_}}\n"
                                       "shm: {enabled: true, name_prefix: a_}\n");
  EXPECT_NE(error.find("shm.enabled would serve /a_spline_shm, the robot's own daemon's object"), std::string::npos)
      << error;
  EXPECT_EQ(load_error("robot: {kind: zsibot_shm, zsibot_shm: {name_prefix: a_}}\n"
                       "shm: {enabled: true, name_prefix: b_}\n"),
            "")
      << "another name serves beside it";
}

TEST(RobotSection, EveryShippedRobotConfigurationLoadsAndNamesItsRobot) {
  const std::string config_dir = std::string(CEREBELLUM_SOURCE_DIR) + "/config/";
  EXPECT_EQ(load_config(config_dir + "robot-cyberdog2.yaml").robot_kind, RobotKind::Cyberdog2MotorSdk);
  EXPECT_EQ(load_config(config_dir + "robot-zsibot.yaml").robot_kind, RobotKind::ZsibotShm);
  EXPECT_EQ(load_config(config_dir + "stack/sim.yaml").robot_kind, RobotKind::Sim);
  EXPECT_EQ(load_config(config_dir + "stack/cyberdog2-motor-sdk.yaml").robot_kind, RobotKind::Cyberdog2MotorSdk);
  const McConfig stacked_zsibot = load_config(config_dir + "stack/zsibot-shm.yaml");
  EXPECT_EQ(stacked_zsibot.robot_kind, RobotKind::ZsibotShm);
  EXPECT_EQ(stacked_zsibot.shm_robot.name_prefix, load_config(config_dir + "stack/sim.yaml").shm.name_prefix)
      << "B reads the shared memory A serves";
}

TEST(RobotSection, SimulationKeysAreRefusedOnARealRobot) {
  const std::string error = load_error("robot: {kind: cyberdog2_motor_sdk, initial_pose: stand}\n");
  EXPECT_NE(error.find("robot.initial_pose applies only to the simulated robot (robot.kind is cyberdog2_motor_sdk)"),
            std::string::npos)
      << error;
}

TEST(RobotSection, TheTerrainIsReadFromItsSpecAndAFileIsFoundBesideTheConfiguration) {
  EXPECT_EQ(default_config().robot.terrain.kind, TerrainKind::Flat);
  const McConfig slope = load_config(write_file("robot: {terrain: 'slope:12'}\n"));
  EXPECT_EQ(slope.robot.terrain.kind, TerrainKind::Slope);
  EXPECT_DOUBLE_EQ(slope.robot.terrain.slope_deg, 12.0);
  const std::string path = write_file("robot: {terrain: 'file:ground.yaml'}\n");
  const McConfig file = load_config(path);
  EXPECT_EQ(file.robot.terrain.file, path.substr(0, path.rfind('/')) + "/ground.yaml");
}

TEST(RobotSection, TheSimulatedLinkIsFastUnlessTheFileGivesItsLatencyInTicks) {
  EXPECT_FALSE(default_config().simulated_link_latency.any());
  const McConfig slow = load_config(write_file("robot: {command_latency_ticks: 2, state_latency_ticks: 3}\n"));
  EXPECT_EQ(slow.simulated_link_latency.command_ticks, 2);
  EXPECT_EQ(slow.simulated_link_latency.state_ticks, 3);
}

TEST(RobotSection, ALatencyOverFiftyMillisecondsOrNotWholeTicksIsRefused) {
  const std::string long_one = load_error("robot: {state_latency_ticks: 26}\n");
  EXPECT_NE(long_one.find("robot.state_latency_ticks must be at most 25 ticks, got 26"), std::string::npos)
      << long_one;
  const std::string fraction = load_error("robot: {command_latency_ticks: 1.5}\n");
  EXPECT_NE(fraction.find("robot.command_latency_ticks must be an integer >= 0, got '1.5'"), std::string::npos)
      << fraction;
  const std::string real = load_error("robot: {kind: zsibot_shm, command_latency_ticks: 1}\n");
  EXPECT_NE(real.find("robot.command_latency_ticks applies only to the simulated robot"), std::string::npos) << real;
}

TEST(RobotSection, AWrongTerrainIsRefusedNamingTheKeyAndTheSpecsError) {
  const std::string error = load_error("robot: {terrain: 'slope:50'}\n");
  EXPECT_NE(error.find("robot.terrain"), std::string::npos) << error;
  EXPECT_NE(error.find("the slope in degrees must be in (0, 35], got 50"), std::string::npos) << error;
  const std::string real = load_error("robot: {kind: cyberdog2_motor_sdk, terrain: 'step:0.05'}\n");
  EXPECT_NE(real.find("robot.terrain applies only to the simulated robot"), std::string::npos) << real;
}

TEST(RobotSection, TheMotorSdkLinkIsRefusedOnTheSimulation) {
  const std::string error = load_error("robot: {kind: sim, cyberdog2_motor_sdk: {link_timeout_s: 0.02}}\n");
  EXPECT_NE(error.find("robot.cyberdog2_motor_sdk applies only to robot.kind cyberdog2_motor_sdk"), std::string::npos)
      << error;
}

TEST(RobotSection, EveryLinkSettingIsCheckedByName) {
  const auto link_error = [](const std::string& entry) { return load_error(motor_sdk_robot(entry)); };
  std::string error = link_error("link_timeout_s: 0.001");
  EXPECT_NE(error.find("robot.cyberdog2_motor_sdk.link_timeout_s must be in [0.004, 0.5], got 0.001"),
            std::string::npos)
      << error;
  error = link_error("control_url: 'not a url'");
  EXPECT_NE(error.find("robot.cyberdog2_motor_sdk.control_url"), std::string::npos) << error;
  EXPECT_NE(error.find("got 'not a url'"), std::string::npos) << error;
  error = link_error("link_timeout: 0.02");
  EXPECT_NE(error.find("robot.cyberdog2_motor_sdk.link_timeout is not a known key"), std::string::npos) << error;
  error = link_error("position_jump_limit: sometimes");
  EXPECT_NE(error.find("robot.cyberdog2_motor_sdk.position_jump_limit must be true or false"), std::string::npos)
      << error;
}

TEST(RobotSection, TheSimulationsToolsAreOffOnARealRobotAndRefusedWhenAskedFor) {
  const McConfig config = load_config(write_file(motor_sdk_robot()));
  EXPECT_EQ(config.sim_truth.rate_hz, 0.0) << "no simulator truth on a real robot";
  EXPECT_FALSE(config.sim_command.enabled) << "push and fault act only on a simulation";
  std::string error = load_error(motor_sdk_robot("", "sim_truth: {rate_hz: 50}\n"));
  EXPECT_NE(error.find("sim_truth.rate_hz must be 0 on a real robot"), std::string::npos) << error;
  error = load_error(motor_sdk_robot("", "sim_command: {enabled: true}\n"));
  EXPECT_NE(error.find("sim_command.enabled must be false on a real robot"), std::string::npos) << error;
}

TEST(RobotSection, AServedInterfaceOnTheRobotsOwnLinkIsRefused) {
  // the defaults serve the motor SDK and the odometry on 7667, the robot's link port
  std::string error = load_error("robot: {kind: cyberdog2_motor_sdk}\n");
  EXPECT_NE(error.find("is the robot's own link (robot.cyberdog2_motor_sdk.control_url)"), std::string::npos)
      << error;
  // whatever the ttl: packets meet on the group and the port (the high-level interface, on by
  // default, publishes the state feedback on motor_sdk's urls)
  error = load_error(motor_sdk_robot("estimator_url: 'udpm://239.255.76.67:7769?ttl=255'"));
  EXPECT_NE(error.find("motor_sdk.estimator_url"), std::string::npos) << error;
  EXPECT_NE(error.find("robot.cyberdog2_motor_sdk.estimator_url"), std::string::npos) << error;
}

}  // namespace
}  // namespace cerebellum
