#include "cli/served_endpoints.hpp"

#include <cstdio>
#include <string>

namespace cerebellum {

std::string served_endpoints(const McConfig& config) {
  std::string out;
  const auto add = [&out](const std::string& clause) { out += (out.empty() ? "" : "; ") + clause; };
  if (config.highlevel.enabled) {
    add("high-level LCM: robot_control_cmd and user_gait_file on " + config.highlevel.command_url +
        ", robot_control_response on " + config.highlevel.response_url + ", global_to_robot on " +
        config.highlevel.odometry_url);
  }
  if (config.motor_sdk.enabled) {
    add("motor SDK LCM: motor_ctrl and spi_data on " + config.motor_sdk.control_url + ", state_estimator on " +
        config.motor_sdk.estimator_url);
  }
  if (config.aliengo.enabled) {
    add("AlienGo UDP: HighCmd / HighState on " + config.aliengo.bind_address + ":" +
        std::to_string(config.aliengo.port));
  }
  if (config.shm.enabled) {
    char mode[8];
    std::snprintf(mode, sizeof(mode), "%04o", config.shm.mode);
    add("shared memory: " + shm_spline_object_name(config.shm.name_prefix) + " and " +
        shm_imu_object_name(config.shm.name_prefix) + " (mode " + mode + ")");
  }
  if (config.sim_truth.rate_hz > 0.0) {
    char rate[32];
    std::snprintf(rate, sizeof(rate), "%g Hz", config.sim_truth.rate_hz);
    add(std::string("simulation: sim_truth at ") + rate + " on " + config.highlevel.odometry_url);
  }
  if (config.sim_command.enabled) {
    add("sim_command (cerebellum push, fault) on " + config.highlevel.odometry_url);
  }
  return out.empty() ? "no client interface (the configuration turns every one off)" : out;
}

}  // namespace cerebellum
