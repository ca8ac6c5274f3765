// Configuration of the CyberDog2 high-level LCM interface (config section `highlevel:`).
#pragma once

#include <string>

#include "io/lcm_common/lcm_network.hpp"

namespace cerebellum {

struct HighLevelLcmConfig {
  // served by default on this host only: ttl=0 keeps every packet on the machine (the robot's
  // network takes ttl=255, config/robot-network.yaml)
  bool enabled = true;
  std::string command_url = lcm_url(kLcmCommandPort, 0);    // robot_control_cmd, user_gait_*
  std::string response_url = lcm_url(kLcmResponsePort, 0);  // robot_control_response, motor_temperature
  std::string odometry_url = lcm_url(kLcmMotorSdkPort, 0);  // global_to_robot (and sim_truth)
  // the newest response is sent again after this much wall time without one, as long as the loop
  // still ticks (slow simulation speeds); 0 disables it
  double response_keepalive_s = 0.1;
};

// empty when the url is usable, else what is wrong; accepted: udpm://<IPv4 multicast group>:<port>
// with optional ?key=value&... options, where ttl (if given) is 0..255
std::string lcm_url_problem(const std::string& url);

}  // namespace cerebellum
