// python (generated modules, standard library only) and c++ read each other's messages
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <array>
#include <cstdint>
#include <cstdio>
#include <string>

#include "lcm/lcm_message_fields.hpp"
#include "motor_ctrl_lcmt.hpp"
#include "robot_control_cmd_lcmt.hpp"
#include "robot_control_response_lcmt.hpp"

namespace cerebellum::test {
namespace {

struct ProcessResult {
  int exit_code = -1;
  std::string output;
};

// runs the helper script with the generated modules on PYTHONPATH; stdout captured
ProcessResult run_interop_script(const std::string& arguments) {
  const std::string command = std::string("PYTHONPATH='") + CEREBELLUM_LCM_PYTHON_DIR + "' '" + CEREBELLUM_PYTHON3 +
                              "' '" + CEREBELLUM_LCM_INTEROP_SCRIPT + "' " + arguments;
  ProcessResult result;
  FILE* pipe = popen(command.c_str(), "r");
  if (pipe == nullptr) return result;
  std::array<char, 4096> chunk{};
  while (std::fgets(chunk.data(), static_cast<int>(chunk.size()), pipe) != nullptr) {
    result.output += chunk.data();
  }
  const int status = pclose(pipe);
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return result;
}

Bytes python_encoding(const std::string& which) {
  ProcessResult result = run_interop_script("encode " + which);
  EXPECT_EQ(result.exit_code, 0) << result.output;
  while (!result.output.empty() && result.output.back() == '\n') result.output.pop_back();
  return bytes_from_hex(result.output);
}

// python packs its double values to float32; the same double expression cast here must match
float as_wire_float(double value) { return static_cast<float>(value); }

TEST(LcmPythonInterop, RobotControlCmdFromPythonDecodesInCpp) {
  const Bytes encoded = python_encoding("robot_control_cmd");
  ASSERT_EQ(encoded.size(), 124u);
  robot_control_cmd_lcmt msg{};
  ASSERT_EQ(msg.decode(encoded.data(), 0, static_cast<int>(encoded.size())), 124);

  EXPECT_EQ(msg.mode, 11);
  EXPECT_EQ(msg.gait_id, 27);
  EXPECT_EQ(msg.contact, 15);
  EXPECT_EQ(msg.life_count, -100);
  const double vel_des[3] = {0.5, -0.25, 1.3};
  const double rpy_des[3] = {0.1, -0.2, 0.3};
  const double pos_des[3] = {0.0, 0.0, 0.235};
  const double ctrl_point[3] = {0.01, 0.02, 0.03};
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(msg.vel_des[i], as_wire_float(vel_des[i])) << i;
    EXPECT_EQ(msg.rpy_des[i], as_wire_float(rpy_des[i])) << i;
    EXPECT_EQ(msg.pos_des[i], as_wire_float(pos_des[i])) << i;
    EXPECT_EQ(msg.ctrl_point[i], as_wire_float(ctrl_point[i])) << i;
  }
  for (int i = 0; i < 6; ++i) {
    EXPECT_EQ(msg.acc_des[i], as_wire_float(i - 2.5)) << i;
    EXPECT_EQ(msg.foot_pose[i], as_wire_float(0.05 * i)) << i;
  }
  EXPECT_EQ(msg.step_height[0], as_wire_float(0.03));
  EXPECT_EQ(msg.step_height[1], as_wire_float(0.05));
  EXPECT_EQ(msg.value, 6);
  EXPECT_EQ(msg.duration, 3000);
}

TEST(LcmPythonInterop, MotorCtrlFromPythonDecodesInCpp) {
  const Bytes encoded = python_encoding("motor_ctrl");
  ASSERT_EQ(encoded.size(), 248u);
  motor_ctrl_lcmt msg{};
  ASSERT_EQ(msg.decode(encoded.data(), 0, static_cast<int>(encoded.size())), 248);
  for (int i = 0; i < 12; ++i) {
    EXPECT_EQ(msg.q_des[i], as_wire_float(0.1 * i - 0.6)) << i;
    EXPECT_EQ(msg.qd_des[i], as_wire_float(-0.5 * i)) << i;
    EXPECT_EQ(msg.kp_des[i], as_wire_float(60.0 + i)) << i;
    EXPECT_EQ(msg.kd_des[i], as_wire_float(2.0 + 0.25 * i)) << i;
    EXPECT_EQ(msg.tau_des[i], as_wire_float(0.5 * (i - 6))) << i;
  }
}

robot_control_response_lcmt known_response() {
  robot_control_response_lcmt msg{};
  msg.mode = 62;
  msg.gait_id = 3;
  msg.contact = 0b1011;
  msg.order_process_bar = 95;
  msg.switch_status = 5;
  msg.ori_error = 1;
  msg.footpos_error = 0x0A5C;
  for (int i = 0; i < 12; ++i) {
    msg.motor_error[i] = static_cast<std::int32_t>(0x80000000u | (1u << i));
  }
  return msg;
}

TEST(LcmPythonInterop, ResponseFromCppDecodesInPython) {
  const ProcessResult result =
      run_interop_script("check robot_control_response " + hex_from_bytes(encode_message(known_response())));
  EXPECT_EQ(result.exit_code, 0) << result.output;
}

TEST(LcmPythonInterop, PythonNoticesAChangedResponse) {
  robot_control_response_lcmt changed = known_response();
  changed.motor_error[7] = 0;
  const ProcessResult result =
      run_interop_script("check robot_control_response " + hex_from_bytes(encode_message(changed)));
  EXPECT_EQ(result.exit_code, 1) << result.output;
  EXPECT_NE(result.output.find("motor_error[7]"), std::string::npos) << result.output;
}

TEST(LcmPythonInterop, PythonRefusesAnotherTypesMessage) {
  const ProcessResult result =
      run_interop_script("check robot_control_response " + hex_from_bytes(encode_message(motor_ctrl_lcmt{})));
  EXPECT_EQ(result.exit_code, 1) << result.output;
}

}  // namespace
}  // namespace cerebellum::test
