#include "cli/sim_command.hpp"

#include <cstdio>
#include <exception>
#include <optional>

#include "observers/console_reporter.hpp"
#include "loop/control_loop.hpp"
#include "loop/mc_config.hpp"
#include "cli/sim_options.hpp"
#include "loop/mc.hpp"
#include "cli/record_tools.hpp"
#include "cli/served_endpoints.hpp"
#include "loop/simulated_robot.hpp"
#include "cli/fault_scenario_file.hpp"
#include "cli/realtime_setup.hpp"
#include "cli/stop_signal.hpp"
#include "cli/client_interfaces.hpp"
#include "io/lcm_sim_control/sim_control_adapter.hpp"
#include "io/lcm_sim_truth/sim_truth_publisher.hpp"

namespace cerebellum {

int run_sim_command(const std::vector<std::string>& args) {
  SimOptions options;
  McConfig config;
  std::vector<TimedFault> faults;
  try {
    options = parse_sim_options(args);
    if (options.help) {
      std::fputs(sim_usage().c_str(), stdout);
      return 0;
    }
    config = options.config_path.empty() ? default_config() : load_config(options.config_path);
    if (options.seed) config.robot.noise.seed = *options.seed;
    if (options.terrain) config.robot.terrain = *options.terrain;
    if (!options.faults_path.empty()) faults = load_fault_scenario(options.faults_path);
    if (config.robot_kind != RobotKind::Sim) {
      std::fprintf(stderr,
                   "cerebellum sim: %s: robot.kind is %s, a real robot; `cerebellum sim` and its tools (the viewer, "
                   "push, fault, sim_truth) run only the simulated one: start it with `cerebellum run --config %s`\n",
                   options.config_path.c_str(), robot_kind_name(config.robot_kind), options.config_path.c_str());
      return 2;
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "cerebellum sim: %s\n", e.what());
    return 2;
  }

  // before any thread starts, so every thread inherits the scheduling and the CPUs
  for (const std::string& line : apply_realtime(config.realtime).lines) std::printf("%s\n", line.c_str());
  StopSignal stop_signal;
  try {
    Mc mc = make_simulated_mc(config, faults);
    ControlLoop& loop = mc.loop();
    // client interfaces attach here: mc.arbiter() sources, loop observers, substep participants
    ConsoleReporter reporter(stdout);
    loop.add_observer(reporter);
    // the client links' faults (`cerebellum fault link ...`): before the adapters that use them
    LinkFaultSet link_faults;
    const bool link_faults_served = config.sim_command.enabled;
    ClientInterfaces interfaces(mc, link_faults_served ? &link_faults : nullptr, stderr);
    // the simulation's ground truth for tools and users' tests; the MC never reads it
    std::optional<SimTruthPublisher> sim_truth;
    if (config.sim_truth.rate_hz > 0.0) {
      sim_truth.emplace(mc.simulation(), config.highlevel.odometry_url, config.sim_truth, config.loop_period_s);
      loop.add_observer(*sim_truth);
    }
    // the simulation's own control channel (pushes): on the odometry URL with sim_truth
    std::optional<SimControlAdapter> sim_control;
    if (config.sim_command.enabled)
      sim_control.emplace(&mc.simulation(), mc.faults(), &link_faults, config.highlevel.odometry_url, stderr);
    SimTools tools(mc, options);

    char speed[32] = "max";
    if (options.speed > 0.0) std::snprintf(speed, sizeof(speed), "%gx real time", options.speed);
    std::printf("cerebellum startup %s: %s\n", startup_name(config.startup), startup_meaning(config.startup));
    std::printf("cerebellum ready: simulated CyberDog2 (%s), %.0f Hz loop, speed %s; serving %s\n",
                config.robot.model_path.c_str(), 1.0 / config.loop_period_s, speed, served_endpoints(config).c_str());
    std::fflush(stdout);
    const RunStats stats = tools.run({options.duration_s, options.speed}, stop_signal.flag());
    reporter.finish();
    const bool tools_ok = tools.finish(stdout, stderr);
    interfaces.finish(stdout);
    if (sim_truth) sim_truth->finish();
    if (sim_control) sim_control->finish(stderr);
    std::printf(
        "cerebellum stopped: %.2f s robot time in %.2f s wall time (%.1fx real time), %llu ticks, "
        "%llu late substeps, %llu pace slips (%.3f s given up), trunk height %.3f m (simulator truth)\n",
        stats.robot_time_s, stats.wall_time_s, stats.wall_time_s > 0 ? stats.robot_time_s / stats.wall_time_s : 0.0,
        static_cast<unsigned long long>(stats.ticks), static_cast<unsigned long long>(stats.late_substeps),
        static_cast<unsigned long long>(stats.pace_slips), stats.slipped_wall_s,
        mc.simulation().ground_truth().position[2]);
    if (!tools_ok) return 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "cerebellum sim: %s\n", e.what());
    return 1;
  }
  return 0;
}

}  // namespace cerebellum
