#include "cli/run_command.hpp"

#include <cstdio>
#include <exception>
#include <memory>
#include <optional>

#include "cli/client_interfaces.hpp"
#include "cli/realtime_setup.hpp"
#include "cli/run_options.hpp"
#include "cli/served_endpoints.hpp"
#include "cli/stop_signal.hpp"
#include "io/lcm_motor_sdk_robot/lcm_motor_sdk_robot.hpp"
#include "io/shm_lowlevel_robot/shm_lowlevel_robot.hpp"
#include "io/lcm_sim_control/sim_control_adapter.hpp"
#include "loop/mc.hpp"
#include "loop/mc_config.hpp"
#include "observers/console_reporter.hpp"

namespace cerebellum {
namespace {

// the loop in real time: a robot does not wait for the controller
constexpr double kRealTime = 1.0;

// the robot the configuration names, through its vendor's low-level interface
std::unique_ptr<HardwareBackend> make_robot(const McConfig& config) {
  if (config.robot_kind == RobotKind::ZsibotShm) return std::make_unique<ShmLowLevelRobot>(config.shm_robot, stderr);
  return std::make_unique<LcmMotorSdkRobot>(config.motor_sdk_robot, stderr);
}

}  // namespace

int run_run_command(const std::vector<std::string>& args) {
  RunCommandOptions options;
  McConfig config;
  try {
    options = parse_run_options(args);
    if (options.help) {
      std::fputs(run_usage().c_str(), stdout);
      return 0;
    }
    config = load_config(options.config_path);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "cerebellum run: %s\n", e.what());
    return 2;
  }
  if (config.robot_kind == RobotKind::Sim) {
    std::fprintf(stderr,
                 "cerebellum run: %s: robot.kind is sim; the simulated robot runs with `cerebellum sim --config %s`\n",
                 options.config_path.c_str(), options.config_path.c_str());
    return 2;
  }

  // before any thread starts, so every thread inherits the scheduling, the CPUs and the blocked signals
  for (const std::string& line : apply_realtime(config.realtime).lines) std::printf("%s\n", line.c_str());
  StopSignal stop_signal;
  try {
    std::unique_ptr<HardwareBackend> backend = make_robot(config);
    HardwareBackend& robot = *backend;
    Mc mc(config, McRobot{std::move(backend), nullptr, nullptr});
    ConsoleReporter reporter(stdout);
    mc.loop().add_observer(reporter);
    ClientInterfaces interfaces(mc, nullptr, stderr);
    // where a simulation listens for push and fault: answered with a refusal, so those tools say
    // why instead of waiting for a simulation that is not there
    std::optional<SimControlAdapter> sim_refusals;
    if (config.highlevel.enabled) {
      sim_refusals.emplace(nullptr, nullptr, nullptr, config.highlevel.odometry_url, stderr);
    }

    std::printf("cerebellum run: activating %s\n", robot.activation_text().c_str());
    std::fflush(stdout);
    if (!robot.activate(stop_signal.flag())) {
      robot.finish(stderr);
      std::fprintf(stderr, "cerebellum run: %s\n", robot.activation_failure().c_str());
      return 1;
    }
    std::printf("cerebellum startup %s: %s\n", startup_name(config.startup), startup_meaning(config.startup));
    std::printf("cerebellum ready: %s, %.0f Hz loop, real time; serving %s\n", robot.description().c_str(),
                1.0 / config.loop_period_s,
                served_endpoints(config).c_str());
    std::fflush(stdout);
    const RunStats stats = mc.loop().run({options.duration_s, kRealTime}, stop_signal.flag());
    reporter.finish();
    interfaces.finish(stdout);
    if (sim_refusals) sim_refusals->finish(stdout);
    robot.finish(stdout);
    std::printf(
        "cerebellum stopped: %.2f s robot time in %.2f s wall time, %llu ticks, %llu late substeps, "
        "%llu pace slips (%.3f s given up)\n",
        stats.robot_time_s, stats.wall_time_s, static_cast<unsigned long long>(stats.ticks),
        static_cast<unsigned long long>(stats.late_substeps), static_cast<unsigned long long>(stats.pace_slips),
        stats.slipped_wall_s);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "cerebellum run: %s\n", e.what());
    return 1;
  }
  return 0;
}

}  // namespace cerebellum
