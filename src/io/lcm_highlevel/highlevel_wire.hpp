// Wire side of the high-level channels: robot_control_cmd and user_gait_file in (raw packets,
// decoded here so malformed ones are told apart), robot_control_response, global_to_robot and
// motor_temperature out.
#pragma once

#include <cstddef>
#include <string>

#include "core/robot_state.hpp"
#include "danger_states_lcmt.hpp"
#include "io/lcm_common/lcm_packet.hpp"
#include "file_recv_lcmt.hpp"
#include "localization_lcmt.hpp"
#include "core/high_level_command.hpp"
#include "robot_control_cmd_lcmt.hpp"
#include "robot_control_response_lcmt.hpp"

namespace cerebellum {

// the channels of user gait files: a text in, a result out
inline constexpr const char* kUserGaitFileChannel = "user_gait_file";
inline constexpr const char* kUserGaitResultChannel = "user_gait_result";

// one raw robot_control_cmd packet (exactly 124 bytes)
WireDecode decode_robot_control_cmd(const void* data, std::size_t size, HighLevelCommand& command);
// the wire message of a command (what a client sends)
robot_control_cmd_lcmt encode_robot_control_cmd(const HighLevelCommand& command);

// one raw file_send_lcmt packet; text gets the string without its terminating nul
WireDecode decode_file_send(const void* data, std::size_t size, std::string& text);

robot_control_response_lcmt make_response(const HighLevelStatus& status);
// xyz, vxyz (world), rpy, omegaBody, vBody of the estimate; timestamp in ns of robot time
localization_lcmt make_localization(const RobotState& state);
// motor_temperature[12] in deg C, joint order FR, FL, RR, RL x abad, hip, knee
danger_states_lcmt make_danger_states(const RobotState& state);
// result 0: accepted, 1: abnormal
file_recv_lcmt make_file_result(bool accepted);

}  // namespace cerebellum
