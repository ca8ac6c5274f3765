// The CyberDog2 LCM network: one multicast group, four ports, each carrying its channels
// (docs/lcm-types.md). The one home of the group and the ports: the configuration's default urls
// and the tools (cmd, status, log, replay) read them here.
#pragma once

#include <array>
#include <string>

namespace cerebellum {

inline constexpr const char* kLcmGroup = "239.255.76.67";
// motor_ctrl, spi_data, motor_ctrl_state, leg_control_data, global_to_robot, sim_truth, sim_command
inline constexpr int kLcmMotorSdkPort = 7667;
inline constexpr int kLcmStateEstimatorPort = 7669;  // state_estimator
inline constexpr int kLcmResponsePort = 7670;        // robot_control_response, motor_temperature
inline constexpr int kLcmCommandPort = 7671;         // robot_control_cmd, user_gait_file, user_gait_result
inline constexpr std::array<int, 4> kLcmPorts{kLcmMotorSdkPort, kLcmStateEstimatorPort, kLcmResponsePort,
                                              kLcmCommandPort};

// udpm://<group>:<port>?ttl=<ttl>
inline std::string lcm_url(int port, int ttl) {
  return std::string("udpm://") + kLcmGroup + ":" + std::to_string(port) + "?ttl=" + std::to_string(ttl);
}

// "7667, 7669, 7670, 7671"
inline std::string lcm_port_list() {
  std::string list;
  for (int port : kLcmPorts) list += (list.empty() ? "" : ", ") + std::to_string(port);
  return list;
}

}  // namespace cerebellum
