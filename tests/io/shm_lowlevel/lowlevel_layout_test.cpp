// lowlevel.h seen from C++: every size and offset of the reference table, each derived again
// from the field sizes, and the bytes a field write lands on.
#include "lowlevel/lowlevel.h"

#include <gtest/gtest.h>

#include <cstring>
#include <type_traits>

namespace {

// sizes built up from the fields, independently of the header's asserts
constexpr std::size_t kFloat = 4;
constexpr std::size_t kJointControl = 5 * kFloat;           // p_des v_des kp kd t_ff
constexpr std::size_t kLegControl = 4 * kJointControl + 4;  // abad hip knee foot + flags
constexpr std::size_t kCmd = 4 * kLegControl + 2 * 4;       // legs[4] + consumer_flags[2]
constexpr std::size_t kJointState = 4 + 3 * kFloat;         // flags p v t
constexpr std::size_t kLegState = 4 * kJointState;
constexpr std::size_t kState = 4 * kLegState + 2 * 4;
constexpr std::size_t kImu = 8 + (3 + 3 + 4) * kFloat;

static_assert(kJointControl == 20 && kLegControl == 84 && kCmd == 344);
static_assert(kJointState == 16 && kLegState == 64 && kState == 264);
static_assert(kCmd + kState == 608 && kImu == 48);

static_assert(sizeof(joint_control_t) == kJointControl);
static_assert(offsetof(joint_control_t, p_des) == 0 * kFloat);
static_assert(offsetof(joint_control_t, v_des) == 1 * kFloat);
static_assert(offsetof(joint_control_t, kp) == 2 * kFloat);
static_assert(offsetof(joint_control_t, kd) == 3 * kFloat);
static_assert(offsetof(joint_control_t, t_ff) == 4 * kFloat);
static_assert(sizeof(leg_control_t) == kLegControl);
static_assert(offsetof(leg_control_t, abad) == 0 * kJointControl);
static_assert(offsetof(leg_control_t, hip) == 1 * kJointControl);
static_assert(offsetof(leg_control_t, knee) == 2 * kJointControl);
static_assert(offsetof(leg_control_t, foot) == 3 * kJointControl);
static_assert(offsetof(leg_control_t, flags) == 4 * kJointControl);
static_assert(sizeof(spline_cmd_data_t) == kCmd);
static_assert(offsetof(spline_cmd_data_t, legs) == 0);
static_assert(offsetof(spline_cmd_data_t, consumer_flags) == 4 * kLegControl);
static_assert(sizeof(joint_state_t) == kJointState);
static_assert(offsetof(joint_state_t, flags) == 0);
static_assert(offsetof(joint_state_t, p) == 4);
static_assert(offsetof(joint_state_t, v) == 4 + kFloat);
static_assert(offsetof(joint_state_t, t) == 4 + 2 * kFloat);
static_assert(sizeof(leg_state_t) == kLegState);
static_assert(offsetof(leg_state_t, abad) == 0 * kJointState);
static_assert(offsetof(leg_state_t, hip) == 1 * kJointState);
static_assert(offsetof(leg_state_t, knee) == 2 * kJointState);
static_assert(offsetof(leg_state_t, foot) == 3 * kJointState);
static_assert(sizeof(spline_state_data_t) == kState);
static_assert(offsetof(spline_state_data_t, legs) == 0);
static_assert(offsetof(spline_state_data_t, consumer_flags) == 4 * kLegState);
static_assert(sizeof(spline_data_t) == kCmd + kState);
static_assert(offsetof(spline_data_t, cmd) == 0);
static_assert(offsetof(spline_data_t, state) == kCmd);
static_assert(sizeof(nav_imu_t) == kImu);
static_assert(offsetof(nav_imu_t, timestamp) == 0);
static_assert(offsetof(nav_imu_t, acc) == 8);
static_assert(offsetof(nav_imu_t, gyro) == 8 + 3 * kFloat);
static_assert(offsetof(nav_imu_t, q) == 8 + 6 * kFloat);
static_assert(sizeof(nav_imu_t::timestamp) == 8, "LP64: size_t is 8 bytes");
static_assert(alignof(spline_data_t) == 1 && alignof(nav_imu_t) == 1, "packed");
static_assert(LOWLEVEL_SPLINE_SHM_SIZE == 10240 && LOWLEVEL_IMU_SHM_SIZE == 1024);
static_assert(CONSUMER_CONTROL == 0 && CONSUMER_OTHER == 1 && CONSUMER_MAX == 2);
static_assert(FRONT_RIGHT == 0 && FRONT_LEFT == 1 && BACK_RIGHT == 2 && BACK_LEFT == 3);
static_assert(std::is_same_v<decltype(joint_state_t::flags), std::int32_t>);
static_assert(std::is_same_v<decltype(leg_control_t::flags), std::int32_t>);

template <typename T>
T read_at(const void* base, std::size_t offset) {
  T value;
  std::memcpy(&value, static_cast<const unsigned char*>(base) + offset, sizeof(T));
  return value;
}

TEST(LowLevelLayout, FieldWritesLandOnTheTableOffsets) {
  spline_data_t data{};
  data.cmd.legs[BACK_RIGHT].knee.t_ff = 1.5f;
  data.cmd.legs[FRONT_RIGHT].foot.p_des = -2.0f;
  data.cmd.consumer_flags[CONSUMER_CONTROL] = 1;
  data.state.legs[FRONT_LEFT].abad.flags = 0x184101;
  data.state.legs[BACK_LEFT].hip.v = 7.0f;
  data.state.consumer_flags[CONSUMER_OTHER] = 1;
  EXPECT_EQ(read_at<float>(&data, 2 * 84 + 40 + 16), 1.5f);
  EXPECT_EQ(read_at<float>(&data, 0 * 84 + 60 + 0), -2.0f);
  EXPECT_EQ(read_at<std::uint32_t>(&data, 336), 1u);
  EXPECT_EQ(read_at<std::int32_t>(&data, 344 + 1 * 64 + 0 + 0), 0x184101);
  EXPECT_EQ(read_at<float>(&data, 344 + 3 * 64 + 16 + 8), 7.0f);
  EXPECT_EQ(read_at<std::uint32_t>(&data, 344 + 256 + 4), 1u);

  nav_imu_t imu{};
  imu.timestamp = 0x0102030405060708ull;
  imu.acc[2] = 9.81f;
  imu.gyro[0] = -0.5f;
  imu.q[0] = 1.0f;
  EXPECT_EQ(read_at<std::uint64_t>(&imu, 0), 0x0102030405060708ull);
  // little-endian: the lowest byte first
  EXPECT_EQ(read_at<std::uint8_t>(&imu, 0), 0x08);
  EXPECT_EQ(read_at<float>(&imu, 8 + 8), 9.81f);
  EXPECT_EQ(read_at<float>(&imu, 20), -0.5f);
  EXPECT_EQ(read_at<float>(&imu, 32), 1.0f);
}

}  // namespace
