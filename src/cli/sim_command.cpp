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
#include "cli/stop_signal.hpp"
#include "io/lcm_highlevel/lcm_highlevel_adapter.hpp"
#include "io/lcm_motor_sdk/lcm_motor_sdk_adapter.hpp"
#include "io/lcm_motor_sdk/lcm_state_feedback.hpp"
#include "io/lcm_sim_control/sim_control_adapter.hpp"
#include "io/udp_aliengo/udp_aliengo_adapter.hpp"
#include "io/lcm_sim_truth/sim_truth_publisher.hpp"
#include "io/shm_lowlevel/shm_lowlevel_port.hpp"

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
    if (!options.faults_path.empty()) faults = load_fault_scenario(options.faults_path);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "cerebellum sim: %s\n", e.what());
    return 2;
  }

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
    std::optional<ShmLowLevelPort> shm;
    if (config.shm.enabled) {
      shm.emplace(config.shm, config.safety, stderr);  // events go where every interface logs
      mc.arbiter().add_low_level_source(shm->source());
      loop.add_substep_participant(*shm);
    }
    std::optional<LcmMotorSdkAdapter> motor_sdk;
    if (config.motor_sdk.enabled) {
      motor_sdk.emplace(config.motor_sdk, stderr);
      if (link_faults_served) motor_sdk->attach_link_faults(link_faults.motor_sdk);
      mc.arbiter().add_low_level_source(motor_sdk->source());
      loop.add_observer(*motor_sdk);
    }
    std::optional<LcmHighLevelAdapter> highlevel;
    if (config.highlevel.enabled) {
      highlevel.emplace(mc.client_port(HighLevelSource::CyberDog2Lcm), mc.user_gait_upload(), config.highlevel,
                        config.loop_period_s, stderr);
      if (link_faults_served) highlevel->attach_link_faults(link_faults.highlevel);
      loop.add_observer(*highlevel);
    }
    std::optional<UdpAliengoAdapter> aliengo;
    if (config.aliengo.enabled) {
      aliengo.emplace(mc.client_port(HighLevelSource::AlienGoUdp), mc.aliengo_source().inbox(), config.aliengo, stderr);
      if (link_faults_served) aliengo->attach_link_faults(link_faults.aliengo);
      loop.add_observer(*aliengo);
    }
    // state_estimator and leg_control_data: listed by both interfaces, published once for both
    std::optional<LcmStateFeedback> state_feedback;
    if (config.motor_sdk.enabled || config.highlevel.enabled) {
      state_feedback.emplace(config.motor_sdk.control_url, config.motor_sdk.estimator_url, config.loop_period_s,
                             motor_sdk ? &motor_sdk->source() : nullptr);
      loop.add_observer(*state_feedback);
    }
    // the simulation's ground truth for tools and users' tests; the MC never reads it
    std::optional<SimTruthPublisher> sim_truth;
    if (config.sim_truth.rate_hz > 0.0) {
      sim_truth.emplace(mc.simulation(), config.highlevel.odometry_url, config.sim_truth, config.loop_period_s);
      loop.add_observer(*sim_truth);
    }
    // the simulation's own control channel (pushes): on the odometry URL with sim_truth
    std::optional<SimControlAdapter> sim_control;
    if (config.sim_command.enabled)
      sim_control.emplace(mc.simulation(), mc.faults(), &link_faults, config.highlevel.odometry_url, stderr);
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
    if (motor_sdk) motor_sdk->finish(stdout);
    if (highlevel) highlevel->finish(stdout);
    if (aliengo) aliengo->finish(stdout);
    if (state_feedback) state_feedback->finish();
    if (sim_truth) sim_truth->finish();
    if (sim_control) sim_control->finish(stderr);
    std::printf(
        "cerebellum stopped: %.2f s robot time in %.2f s wall time (%.1fx real time), %llu ticks, "
        "%llu late substeps, trunk height %.3f m (simulator truth)\n",
        stats.robot_time_s, stats.wall_time_s, stats.wall_time_s > 0 ? stats.robot_time_s / stats.wall_time_s : 0.0,
        static_cast<unsigned long long>(stats.ticks), static_cast<unsigned long long>(stats.late_substeps),
        mc.simulation().ground_truth().position[2]);
    if (!tools_ok) return 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "cerebellum sim: %s\n", e.what());
    return 1;
  }
  return 0;
}

}  // namespace cerebellum
