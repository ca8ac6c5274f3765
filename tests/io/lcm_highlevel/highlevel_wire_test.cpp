#include "io/lcm_highlevel/highlevel_wire.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "io/lcm_highlevel/big_endian_writer.hpp"
#include "motions/user_gait_file.hpp"

namespace cerebellum {
namespace {

using test::BigEndianWriter;
using Bytes = std::vector<std::uint8_t>;

WireDecode decode(const Bytes& bytes, HighLevelCommand& command) {
  return decode_robot_control_cmd(bytes.data(), bytes.size(), command);
}

TEST(HighLevelWire, CommandFieldsComeFromTheirWirePositions) {
  const Bytes packet = test::robot_control_cmd_packet(11, 27, 0x0E, -3, 1.0f, 6, 3000);
  ASSERT_EQ(packet.size(), 124u);
  HighLevelCommand c;
  ASSERT_EQ(decode(packet, c), WireDecode::Ok);
  EXPECT_EQ(c.mode, 11);
  EXPECT_EQ(c.gait_id, 27);
  EXPECT_EQ(c.contact, 0x0E);
  EXPECT_EQ(c.life_count, -3);
  // the 26 floats in declaration order: 1.0, 1.25, 1.5, ...
  std::vector<float> floats;
  for (const auto* array : {c.vel_des.data(), c.rpy_des.data(), c.pos_des.data()})
    floats.insert(floats.end(), array, array + 3);
  floats.insert(floats.end(), c.acc_des.begin(), c.acc_des.end());
  floats.insert(floats.end(), c.ctrl_point.begin(), c.ctrl_point.end());
  floats.insert(floats.end(), c.foot_pose.begin(), c.foot_pose.end());
  floats.insert(floats.end(), c.step_height.begin(), c.step_height.end());
  ASSERT_EQ(floats.size(), 26u);
  for (std::size_t i = 0; i < floats.size(); ++i) EXPECT_EQ(floats[i], 1.0f + 0.25f * static_cast<float>(i)) << i;
  EXPECT_EQ(c.value, 6);
  EXPECT_EQ(c.duration, 3000);
}

TEST(HighLevelWire, EncodedCommandIsTheHandBuiltPacket) {
  HighLevelCommand c;
  ASSERT_EQ(decode(test::robot_control_cmd_packet(-1, 110, 15, 127, -2.0f, -7, 0), c), WireDecode::Ok);
  const robot_control_cmd_lcmt message = encode_robot_control_cmd(c);
  Bytes encoded(static_cast<std::size_t>(message.getEncodedSize()));
  ASSERT_EQ(message.encode(encoded.data(), 0, static_cast<int>(encoded.size())), 124);
  EXPECT_EQ(encoded, test::robot_control_cmd_packet(-1, 110, 15, 127, -2.0f, -7, 0));
}

TEST(HighLevelWire, MalformedCommandsAreToldApart) {
  HighLevelCommand c;
  const Bytes good = test::robot_control_cmd_packet(12, 0, 15, 1, 0.0f, 0, 0);
  EXPECT_EQ(decode(Bytes{}, c), WireDecode::Truncated);
  EXPECT_EQ(decode(Bytes(good.begin(), good.begin() + 7), c), WireDecode::Truncated);
  EXPECT_EQ(decode(Bytes(good.begin(), good.begin() + 8), c), WireDecode::Truncated);
  EXPECT_EQ(decode(Bytes(good.begin(), good.end() - 1), c), WireDecode::Truncated);
  Bytes longer = good;
  longer.push_back(0);
  EXPECT_EQ(decode(longer, c), WireDecode::Oversized);
  Bytes foreign = good;
  foreign[7] ^= 0x01;
  EXPECT_EQ(decode(foreign, c), WireDecode::WrongFingerprint);
  EXPECT_EQ(decode(Bytes(foreign.begin(), foreign.begin() + 8), c), WireDecode::WrongFingerprint);
  // a response packet on the command channel
  Bytes response(64, 0);
  BigEndianWriter w;
  w.u64(test::kRobotControlResponseHash);
  std::copy(w.bytes().begin(), w.bytes().end(), response.begin());
  EXPECT_EQ(decode(response, c), WireDecode::WrongFingerprint);
  // nothing was written by the failures
  EXPECT_EQ(c.mode, 0);
  EXPECT_EQ(c.life_count, 0);
}

TEST(HighLevelWire, FileSendTextWithoutItsNul) {
  std::string text;
  const Bytes packet = test::file_send_packet("# Gait Def\n");
  ASSERT_EQ(decode_file_send(packet.data(), packet.size(), text), WireDecode::Ok);
  EXPECT_EQ(text, "# Gait Def\n");
  const Bytes empty = test::file_send_packet("");
  ASSERT_EQ(decode_file_send(empty.data(), empty.size(), text), WireDecode::Ok);
  EXPECT_EQ(text, "");
}

TEST(HighLevelWire, MalformedFileSendIsRefused) {
  std::string text = "untouched";
  const Bytes good = test::file_send_packet("abc");
  EXPECT_EQ(decode_file_send(good.data(), 11, text), WireDecode::Truncated);  // no length
  EXPECT_EQ(decode_file_send(good.data(), good.size() - 1, text), WireDecode::Truncated);
  Bytes longer = good;
  longer.push_back('x');
  EXPECT_EQ(decode_file_send(longer.data(), longer.size(), text), WireDecode::Oversized);
  Bytes no_nul = good;
  no_nul.back() = 'd';
  EXPECT_EQ(decode_file_send(no_nul.data(), no_nul.size(), text), WireDecode::Truncated);
  Bytes zero_length = BigEndianWriter().u64(test::kFileSendHash).i32(0).bytes();
  EXPECT_EQ(decode_file_send(zero_length.data(), zero_length.size(), text), WireDecode::Truncated);
  Bytes negative = BigEndianWriter().u64(test::kFileSendHash).i32(-1).bytes();
  EXPECT_EQ(decode_file_send(negative.data(), negative.size(), text), WireDecode::Oversized);
  const Bytes huge = test::file_send_packet(std::string(kMaxUserGaitFileBytes + 1, 'a'));
  EXPECT_EQ(decode_file_send(huge.data(), huge.size(), text), WireDecode::Oversized);
  Bytes foreign = good;
  foreign[0] ^= 0x80;
  EXPECT_EQ(decode_file_send(foreign.data(), foreign.size(), text), WireDecode::WrongFingerprint);
  EXPECT_EQ(text, "untouched");
}

TEST(HighLevelWire, ResponseBytesFollowTheReferenceLayout) {
  HighLevelStatus status;
  status.mode = 62;
  status.gait_id = 3;
  status.contact = 0x0B;
  status.order_process_bar = 96;
  status.switch_status = SwitchStatus::BanTransition;
  status.ori_error = 1;
  status.footpos_error = 0x801;
  status.motor_faults[4] = kMotorTemperatureWarning;
  const robot_control_response_lcmt message = make_response(status);
  Bytes encoded(64);
  ASSERT_EQ(message.encode(encoded.data(), 0, 64), 64);
  BigEndianWriter expected;
  expected.u64(test::kRobotControlResponseHash).i8(62).i8(3).i8(0x0B).i8(96).i8(5).i8(1).i16(0x801);
  for (int i = 0; i < 12; ++i) expected.i32(static_cast<std::int32_t>(i == 4 ? 0x81000000u : 0x80000000u));
  EXPECT_EQ(encoded, expected.bytes());
}

TEST(HighLevelWire, LocalizationFromTheEstimate) {
  RobotState state;
  state.time_s = 12.345678901;
  state.position_world = {1.0, -2.0, 0.25};
  state.velocity_world = {0.5, 0.1, -0.05};
  state.rpy = {0.01, -0.02, 3.0};
  state.omega_body = {0.3, 0.2, 0.1};
  state.velocity_body = {0.4, -0.3, 0.0};
  const localization_lcmt m = make_localization(state);
  Bytes encoded(76);
  ASSERT_EQ(m.encode(encoded.data(), 0, 76), 76);
  BigEndianWriter expected;
  expected.u64(test::kLocalizationHash);
  for (const Eigen::Vector3d* v :
       {&state.position_world, &state.velocity_world, &state.rpy, &state.omega_body, &state.velocity_body}) {
    for (int i = 0; i < 3; ++i) expected.f32(static_cast<float>((*v)[i]));
  }
  expected.u64(12345678901ull);
  EXPECT_EQ(encoded, expected.bytes());
}

TEST(HighLevelWire, TemperaturesInJointOrder) {
  RobotState state;
  for (std::size_t i = 0; i < kNumJoints; ++i) state.temperature_c[i] = 30.0 + static_cast<double>(i);
  const danger_states_lcmt m = make_danger_states(state);
  Bytes encoded(56);
  ASSERT_EQ(m.encode(encoded.data(), 0, 56), 56);
  BigEndianWriter expected;
  expected.u64(test::kDangerStatesHash);
  for (int i = 0; i < 12; ++i) expected.f32(30.0f + static_cast<float>(i));
  EXPECT_EQ(encoded, expected.bytes());
}

TEST(HighLevelWire, FileResultZeroOnlyWhenAccepted) {
  Bytes encoded(9);
  ASSERT_EQ(make_file_result(true).encode(encoded.data(), 0, 9), 9);
  EXPECT_EQ(encoded, BigEndianWriter().u64(test::kFileRecvHash).i8(0).bytes());
  ASSERT_EQ(make_file_result(false).encode(encoded.data(), 0, 9), 9);
  EXPECT_EQ(encoded, BigEndianWriter().u64(test::kFileRecvHash).i8(1).bytes());
}

}  // namespace
}  // namespace cerebellum
