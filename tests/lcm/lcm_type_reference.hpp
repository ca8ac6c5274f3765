#pragma once
// the reference tables for every lcm type (cyberdog2-highlevel.md and cyberdog2-lowlevel.md,
// section 2): fields as member pointers in wire order, wire fingerprint, encoded size

#include <gtest/gtest.h>

#include <cstddef>
#include <string>
#include <tuple>

#include "danger_states_lcmt.hpp"
#include "file_recv_lcmt.hpp"
#include "file_send_lcmt.hpp"
#include "leg_control_data_lcmt.hpp"
#include "localization_lcmt.hpp"
#include "motor_ctrl_lcmt.hpp"
#include "motor_ctrl_state_lcmt.hpp"
#include "robot_control_cmd_lcmt.hpp"
#include "robot_control_response_lcmt.hpp"
#include "spi_data_t.hpp"
#include "state_estimator_lcmt.hpp"

namespace cerebellum::test {

// fixed-size types: encoded_size is the table's size
template <class Msg>
struct LcmReference;

template <>
struct LcmReference<robot_control_cmd_lcmt> {
  using M = robot_control_cmd_lcmt;
  static constexpr const char* fingerprint_hex = "8ed6c3c52d5f2dea";
  static constexpr std::size_t encoded_size = 124;
  static constexpr auto fields =
      std::make_tuple(&M::mode, &M::gait_id, &M::contact, &M::life_count, &M::vel_des, &M::rpy_des, &M::pos_des,
                      &M::acc_des, &M::ctrl_point, &M::foot_pose, &M::step_height, &M::value, &M::duration);
};

template <>
struct LcmReference<robot_control_response_lcmt> {
  using M = robot_control_response_lcmt;
  static constexpr const char* fingerprint_hex = "90bb53042ddb518e";
  static constexpr std::size_t encoded_size = 64;
  static constexpr auto fields = std::make_tuple(&M::mode, &M::gait_id, &M::contact, &M::order_process_bar,
                                                 &M::switch_status, &M::ori_error, &M::footpos_error, &M::motor_error);
};

// variable size: 8 fingerprint + 4 length + text + 1 terminating nul
template <>
struct LcmReference<file_send_lcmt> {
  using M = file_send_lcmt;
  static constexpr const char* fingerprint_hex = "21bf37099b9d5e15";
  static std::size_t encoded_size_of(const M& msg) { return 8 + 4 + msg.data.size() + 1; }
  static constexpr auto fields = std::make_tuple(&M::data);
};

template <>
struct LcmReference<file_recv_lcmt> {
  using M = file_recv_lcmt;
  static constexpr const char* fingerprint_hex = "ececa67e3eda6d7d";
  static constexpr std::size_t encoded_size = 9;
  static constexpr auto fields = std::make_tuple(&M::result);
};

template <>
struct LcmReference<localization_lcmt> {
  using M = localization_lcmt;
  static constexpr const char* fingerprint_hex = "fc48de06e344fb12";
  static constexpr std::size_t encoded_size = 76;
  static constexpr auto fields = std::make_tuple(&M::xyz, &M::vxyz, &M::rpy, &M::omegaBody, &M::vBody, &M::timestamp);
};

template <>
struct LcmReference<danger_states_lcmt> {
  using M = danger_states_lcmt;
  static constexpr const char* fingerprint_hex = "3833e1f8ac8e5548";
  static constexpr std::size_t encoded_size = 56;
  static constexpr auto fields = std::make_tuple(&M::motor_temperature);
};

template <>
struct LcmReference<state_estimator_lcmt> {
  using M = state_estimator_lcmt;
  static constexpr const char* fingerprint_hex = "18d2c31121532f5e";
  static constexpr std::size_t encoded_size = 192;
  static constexpr auto fields = std::make_tuple(&M::p, &M::vWorld, &M::vBody, &M::p_abs, &M::vWorld_abs, &M::vBody_abs,
                                                 &M::vRemoter, &M::rpy, &M::omegaBody, &M::omegaWorld, &M::quat,
                                                 &M::aBody, &M::aWorld, &M::contactEstimate, &M::timestamp);
};

template <>
struct LcmReference<leg_control_data_lcmt> {
  using M = leg_control_data_lcmt;
  static constexpr const char* fingerprint_hex = "4d630488c94854d7";
  static constexpr std::size_t encoded_size = 392;
  static constexpr auto fields =
      std::make_tuple(&M::q, &M::qd, &M::p, &M::v, &M::tau_est, &M::force_est, &M::force_desired, &M::q_abad_limit,
                      &M::q_hip_limit, &M::q_knee_limit);
};

template <>
struct LcmReference<motor_ctrl_lcmt> {
  using M = motor_ctrl_lcmt;
  static constexpr const char* fingerprint_hex = "7bb7cc457845acac";
  static constexpr std::size_t encoded_size = 248;
  static constexpr auto fields = std::make_tuple(&M::q_des, &M::qd_des, &M::kp_des, &M::kd_des, &M::tau_des);
};

template <>
struct LcmReference<motor_ctrl_state_lcmt> {
  using M = motor_ctrl_state_lcmt;
  static constexpr const char* fingerprint_hex = "55fbef7bec06b5d4";
  static constexpr std::size_t encoded_size = 14;
  static constexpr auto fields = std::make_tuple(&M::err_flag, &M::ctrl_topic_interval);
};

template <>
struct LcmReference<spi_data_t> {
  using M = spi_data_t;
  static constexpr const char* fingerprint_hex = "9b4a1512c17ce8c6";
  static constexpr std::size_t encoded_size = 268;
  static constexpr auto fields = std::make_tuple(
      &M::q_abad, &M::q_hip, &M::q_knee, &M::qd_abad, &M::qd_hip, &M::qd_knee, &M::flags, &M::spi_driver_status,
      &M::tau_abad, &M::tau_hip, &M::tau_knee, &M::tmp_abad, &M::tmp_hip, &M::tmp_knee, &M::reserve);
};

// the table's size for this message (fixed, or from the string length)
template <class Msg>
std::size_t reference_encoded_size(const Msg& msg) {
  if constexpr (requires { LcmReference<Msg>::encoded_size; }) {
    (void)msg;
    return LcmReference<Msg>::encoded_size;
  } else {
    return LcmReference<Msg>::encoded_size_of(msg);
  }
}

// every type, for typed tests; named by its lcm type name
using AllLcmTypes = ::testing::Types<robot_control_cmd_lcmt, robot_control_response_lcmt, file_send_lcmt,
                                     file_recv_lcmt, localization_lcmt, danger_states_lcmt, state_estimator_lcmt,
                                     leg_control_data_lcmt, motor_ctrl_lcmt, motor_ctrl_state_lcmt, spi_data_t>;

struct LcmTypeName {
  template <class Msg>
  static std::string GetName(int) {
    return Msg::getTypeName();
  }
};

}  // namespace cerebellum::test
