// The AlienGo wire format: the vendor library's five CRC vectors, the byte offsets of the fields
// the reference lists (written by byte position, not through the struct), and the decoder's
// refusals: wrong length, bad CRC, low-level flag, NaN / Inf.
#include "io/udp_aliengo/aliengo_wire.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <vector>

#include "unitree_legged_sdk/comm.h"

namespace cerebellum {
namespace {

namespace sdk = UNITREE_LEGGED_SDK;

void put_float(std::vector<std::uint8_t>& frame, std::size_t offset, float value) {
  std::memcpy(frame.data() + offset, &value, 4);
}

// the CRC the reference defines, computed here independently: CRC-32/MPEG-2 over each word's
// bytes taken most significant first (the word byte-swapped), byte by byte
std::uint32_t mpeg2_over_swapped_words(const std::vector<std::uint8_t>& frame) {
  std::uint32_t crc = 0xFFFFFFFFu;
  const std::size_t words = frame.size() / 4 - 1;
  for (std::size_t w = 0; w < words; ++w) {
    for (int b = 3; b >= 0; --b) {
      crc ^= static_cast<std::uint32_t>(frame[4 * w + static_cast<std::size_t>(b)]) << 24;
      for (int bit = 0; bit < 8; ++bit) crc = (crc & 0x80000000u) ? (crc << 1) ^ 0x04C11DB7u : crc << 1;
    }
  }
  return crc;
}

TEST(AlienGoCrc, MatchesTheVendorLibrarysFiveVectors) {
  std::vector<std::uint8_t> cmd(113, 0);
  EXPECT_EQ(sdk::frame_crc(cmd.data(), cmd.size()), 0x3040C10Fu);
  cmd[10] = 1;
  put_float(cmd, 29, 0.7f);
  EXPECT_EQ(sdk::frame_crc(cmd.data(), cmd.size()), 0x9953BD6Cu);
  std::fill(cmd.begin(), cmd.end(), 0);
  cmd[10] = 2;
  put_float(cmd, 41, 0.2f);
  put_float(cmd, 49, 0.3f);
  EXPECT_EQ(sdk::frame_crc(cmd.data(), cmd.size()), 0xB6BF284Au);
  std::fill(cmd.begin(), cmd.end(), 0);
  cmd[0] = 0xF0;
  EXPECT_EQ(sdk::frame_crc(cmd.data(), cmd.size()), 0x9DEF98E3u);
  const std::vector<std::uint8_t> state(244, 0);
  EXPECT_EQ(sdk::frame_crc(state.data(), state.size()), 0x37DB79C2u);
}

TEST(AlienGoCrc, AgreesWithMpeg2OverByteSwappedWordsOnArbitraryFrames) {
  std::vector<std::uint8_t> frame(244);
  unsigned seed = 12345;
  for (int trial = 0; trial < 20; ++trial) {
    for (auto& byte : frame) byte = static_cast<std::uint8_t>((seed = seed * 1103515245u + 12345u) >> 16);
    EXPECT_EQ(sdk::frame_crc(frame.data(), frame.size()), mpeg2_over_swapped_words(frame));
  }
}

TEST(AlienGoWire, DecodesEveryFieldFromItsByteOffset) {
  std::vector<std::uint8_t> frame(113, 0);
  frame[0] = 0x00;
  frame[10] = 3;                 // mode
  frame[11] = 2;                 // gaitType
  frame[12] = 1;                 // speedLevel
  put_float(frame, 13, 0.01f);   // dFootRaiseHeight
  put_float(frame, 17, -0.05f);  // dBodyHeight
  put_float(frame, 21, 1.5f);
  put_float(frame, 25, -0.5f);
  put_float(frame, 29, 0.1f);
  put_float(frame, 33, 0.2f);
  put_float(frame, 37, 0.3f);
  put_float(frame, 41, 0.4f);
  put_float(frame, 45, -0.1f);
  put_float(frame, 49, 0.6f);
  sdk::store_crc(frame.data(), frame.size());
  AlienGoCommand c;
  ASSERT_EQ(decode_high_cmd(frame.data(), frame.size(), c), AlienGoDecode::Ok);
  EXPECT_EQ(c.mode, 3);
  EXPECT_EQ(c.gait_type, 2);
  EXPECT_EQ(c.speed_level, 1);
  EXPECT_FLOAT_EQ(c.foot_raise_m, 0.01f);
  EXPECT_FLOAT_EQ(c.body_height_m, -0.05f);
  EXPECT_FLOAT_EQ(c.position[0], 1.5f);
  EXPECT_FLOAT_EQ(c.position[1], -0.5f);
  EXPECT_FLOAT_EQ(c.rpy[0], 0.1f);
  EXPECT_FLOAT_EQ(c.rpy[1], 0.2f);
  EXPECT_FLOAT_EQ(c.rpy[2], 0.3f);
  EXPECT_FLOAT_EQ(c.velocity[0], 0.4f);
  EXPECT_FLOAT_EQ(c.velocity[1], -0.1f);
  EXPECT_FLOAT_EQ(c.yaw_speed, 0.6f);
  // the CRC is stored little-endian in the last four bytes
  const std::uint32_t crc = sdk::frame_crc(frame.data(), frame.size());
  EXPECT_EQ(frame[109], crc & 0xFF);
  EXPECT_EQ(frame[112], crc >> 24);
}

TEST(AlienGoWire, EncodesHighStateFieldsAtTheirByteOffsets) {
  AlienGoFeedback f;
  f.mode = 6;
  f.quaternion_wxyz = {0.5, 0.1, 0.2, 0.3};
  f.rpy = {0.01, 0.02, 0.03};
  f.temperature_c = 31;
  f.position = {1.0, 2.0, 0.25};
  f.velocity = {0.4, 0.5, 0.6};
  f.yaw_speed = 0.7;
  f.foot_position[3] = {-0.2, 0.1, -0.25};
  f.foot_velocity[2] = {0.01, 0.02, 0.03};
  f.foot_force = {100, 200, 300, 400};
  std::uint8_t frame[kHighStateBytes];
  encode_high_state(f, frame);
  const auto f32 = [&](std::size_t offset) {
    float v;
    std::memcpy(&v, frame + offset, 4);
    return v;
  };
  EXPECT_EQ(frame[10], 6);
  EXPECT_FLOAT_EQ(f32(11), 0.5f);            // imu.quaternion[0] = w
  EXPECT_FLOAT_EQ(f32(11 + 40 + 8), 0.03f);  // imu.rpy[2]
  EXPECT_EQ(static_cast<std::int8_t>(frame[11 + 52]), 31);
  EXPECT_FLOAT_EQ(f32(64 + 4), 2.0f);             // position[1]
  EXPECT_FLOAT_EQ(f32(76 + 8), 0.6f);             // velocity[2]
  EXPECT_FLOAT_EQ(f32(88), 0.7f);                 // yawSpeed
  EXPECT_FLOAT_EQ(f32(92 + 3 * 12 + 8), -0.25f);  // footPosition2Body[3].z
  EXPECT_FLOAT_EQ(f32(140 + 2 * 12 + 4), 0.02f);  // footSpeed2Body[2].y
  std::int16_t force;
  std::memcpy(&force, frame + 188 + 2 * 3, 2);
  EXPECT_EQ(force, 400);
  EXPECT_EQ(sdk::stored_crc(frame, sizeof frame), sdk::frame_crc(frame, sizeof frame));
  AlienGoFeedback back;
  ASSERT_TRUE(decode_high_state(frame, sizeof frame, back));
  EXPECT_EQ(back.foot_force[2], 300);
}

std::vector<std::uint8_t> good_frame() {
  AlienGoCommand c;
  c.mode = 2;
  c.velocity = {0.3f, 0.0f};
  std::uint8_t frame[kHighCmdBytes];
  encode_high_cmd(c, frame);
  return {frame, frame + sizeof frame};
}

TEST(AlienGoWire, RefusesShortLongCorruptedLowLevelAndNonFiniteFrames) {
  AlienGoCommand c;
  std::vector<std::uint8_t> frame = good_frame();
  ASSERT_EQ(decode_high_cmd(frame.data(), frame.size(), c), AlienGoDecode::Ok);
  EXPECT_EQ(decode_high_cmd(frame.data(), 112, c), AlienGoDecode::WrongLength);
  std::vector<std::uint8_t> longer = frame;
  longer.push_back(0);
  EXPECT_EQ(decode_high_cmd(longer.data(), longer.size(), c), AlienGoDecode::WrongLength);
  EXPECT_EQ(decode_high_cmd(nullptr, 113, c), AlienGoDecode::WrongLength);
  std::vector<std::uint8_t> flipped = frame;
  flipped[42] ^= 0x01;
  EXPECT_EQ(decode_high_cmd(flipped.data(), flipped.size(), c), AlienGoDecode::BadCrc);
  std::vector<std::uint8_t> low = frame;
  low[0] = sdk::LOWLEVEL;
  sdk::store_crc(low.data(), low.size());
  EXPECT_EQ(decode_high_cmd(low.data(), low.size(), c), AlienGoDecode::LowLevel);
  for (float bad : {std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity()}) {
    for (std::size_t offset : {13u, 17u, 21u, 29u, 41u, 49u}) {
      std::vector<std::uint8_t> poisoned = frame;
      put_float(poisoned, offset, bad);
      sdk::store_crc(poisoned.data(), poisoned.size());
      EXPECT_EQ(decode_high_cmd(poisoned.data(), poisoned.size(), c), AlienGoDecode::NonFinite) << offset;
    }
  }
}

// the seed's section 1.3 snippet writes footRaiseHeight, its table dFootRaiseHeight: both compile,
// name the same 4 bytes at the reference's offset 13, and the struct keeps its 113 bytes
static_assert(sizeof(sdk::HighCmd) == 113);
static_assert(offsetof(sdk::HighCmd, footRaiseHeight) == 13 && offsetof(sdk::HighCmd, dFootRaiseHeight) == 13);
static_assert(offsetof(sdk::HighCmd, dBodyHeight) == 17);

TEST(AlienGoWire, TheSeedsSnippetWithFootRaiseHeightCompilesAndSetsTheSameFieldAsDFootRaiseHeight) {
  // section 1.3, as the seed writes it (InitCmdData sets only levelFlag)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"  // the seed's "= {0}"
  sdk::HighCmd mycmd = {0};
#pragma GCC diagnostic pop
  mycmd.levelFlag = sdk::HIGHLEVEL;
  mycmd.mode = 2;
  mycmd.gaitType = 1;
  mycmd.velocity[0] = 0.2f;
  mycmd.footRaiseHeight = 0.1;
  std::uint8_t frame[sizeof(sdk::HighCmd)];
  std::memcpy(frame, &mycmd, sizeof frame);
  sdk::store_crc(frame, sizeof frame);
  AlienGoCommand decoded;
  ASSERT_EQ(decode_high_cmd(frame, sizeof frame, decoded), AlienGoDecode::Ok);
  EXPECT_FLOAT_EQ(decoded.foot_raise_m, 0.1f);
  EXPECT_FLOAT_EQ(decoded.velocity[0], 0.2f);
  // the table's name: the same bytes
  mycmd.dFootRaiseHeight = -0.02f;
  std::memcpy(frame, &mycmd, sizeof frame);
  sdk::store_crc(frame, sizeof frame);
  ASSERT_EQ(decode_high_cmd(frame, sizeof frame, decoded), AlienGoDecode::Ok);
  EXPECT_FLOAT_EQ(decoded.foot_raise_m, -0.02f);
  float at_13;
  std::memcpy(&at_13, frame + 13, sizeof at_13);
  EXPECT_FLOAT_EQ(at_13, -0.02f);
}

}  // namespace
}  // namespace cerebellum
