// Wire side of the motor SDK channels: motor_ctrl in, spi_data and motor_ctrl_state out.
// Joint values on the wire use the MC's internal convention (hip and knee negated).
#pragma once

#include <cstddef>
#include <cstdint>

#include "core/robot_readings.hpp"
#include "core/robot_state.hpp"
#include "core/types.hpp"
#include "io/lcm_common/lcm_packet.hpp"
#include "lowlevel/motor_sdk/motor_sdk_source.hpp"
#include "motor_ctrl_lcmt.hpp"
#include "motor_ctrl_state_lcmt.hpp"
#include "spi_data_t.hpp"

namespace cerebellum {

// the channels, served by the MC's motor SDK and read by the motor SDK robot backend
inline constexpr const char* kMotorCtrlChannel = "motor_ctrl";
inline constexpr const char* kMotorCtrlStateChannel = "motor_ctrl_state";
inline constexpr const char* kSpiDataChannel = "spi_data";

// decodes one raw motor_ctrl packet (exactly 248 bytes) into an SDK-convention command (kp, kd unchanged;
// q_des, qd_des, tau_des flipped); NaN/Inf pass through, the mailbox rejects them
WireDecode decode_motor_ctrl(const void* data, std::size_t size, JointCommand& sdk_command);

// the wire message of an SDK-convention command (what a client sends)
motor_ctrl_lcmt encode_motor_ctrl(const JointCommand& sdk_command);

// what a robot's spi_data says, in the SDK convention (hip and knee flipped back), temperatures in
// deg C, each flags word split into MotorFault bits and the driver's mode: the inverse of
// make_spi_data (the motor SDK robot backend reads the robot with it)
JointReading joint_state_from_spi_data(const spi_data_t& message);

// spi_data.flags carry each motor's MotorFault bits as motor_error words (io/common)
spi_data_t make_spi_data(const RobotState& state);
motor_ctrl_state_lcmt make_motor_ctrl_state(const MotorSdkStatus& status);

}  // namespace cerebellum
