// The AlienGo high-level wire format (HighCmd 113 bytes, HighState 244 bytes, packed,
// little-endian) and its CRC, written from docs/aliengo-udp.md. This header is the one home of the
// layout: the client library and the MC's UDP adapter (src/io/udp_aliengo) both read it.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>

namespace UNITREE_LEGGED_SDK {

constexpr uint8_t HIGHLEVEL = 0x00;
constexpr uint8_t LOWLEVEL = 0xff;
constexpr uint8_t TRIGERLEVEL = 0xf0;  // the vendor's "sport mode" trigger

#pragma pack(1)

struct Cartesian {
  float x;
  float y;
  float z;
};

struct IMU {
  float quaternion[4];  // w, x, y, z
  float gyroscope[3];
  float accelerometer[3];
  float rpy[3];
  int8_t temperature;
};

struct LED {
  uint8_t r;
  uint8_t g;
  uint8_t b;
};

struct HighCmd {
  uint8_t levelFlag;
  uint16_t commVersion;
  uint16_t robotID;
  uint32_t SN;
  uint8_t bandWidth;
  uint8_t mode;
  uint8_t gaitType;    // 0 trot, 1 trot running, 2 climb stairs
  uint8_t speedLevel;  // 0 low, 1 medium, 2 high (mode 3)
  // the seed's table spells it dFootRaiseHeight, its section 1.3 snippet footRaiseHeight: both
  // names are the same 4 bytes at offset 13 (an anonymous union: the layout does not change)
  union {
    float dFootRaiseHeight;
    float footRaiseHeight;
  };
  float dBodyHeight;
  float position[2];
  float rpy[3];
  float velocity[2];
  float yawSpeed;
  LED led[4];
  uint8_t wirelessRemote[40];
  uint32_t reserve;
  uint32_t crc;
};

struct HighState {
  uint8_t levelFlag;
  uint16_t commVersion;
  uint16_t robotID;
  uint32_t SN;
  uint8_t bandWidth;
  uint8_t mode;
  IMU imu;
  float position[3];
  float velocity[3];
  float yawSpeed;
  Cartesian footPosition2Body[4];
  Cartesian footSpeed2Body[4];
  int16_t footForce[4];
  uint8_t wirelessRemote[40];
  uint32_t reserve;
  uint32_t crc;
};

#pragma pack()

static_assert(sizeof(IMU) == 53, "IMU is 53 bytes");
static_assert(sizeof(HighCmd) == 113, "HighCmd is 113 bytes");
static_assert(sizeof(HighState) == 244, "HighState is 244 bytes");
static_assert(offsetof(HighCmd, mode) == 10 && offsetof(HighCmd, gaitType) == 11 &&
                  offsetof(HighCmd, speedLevel) == 12 && offsetof(HighCmd, dFootRaiseHeight) == 13 &&
                  offsetof(HighCmd, footRaiseHeight) == 13 && offsetof(HighCmd, dBodyHeight) == 17 &&
                  offsetof(HighCmd, position) == 21 && offsetof(HighCmd, rpy) == 29 &&
                  offsetof(HighCmd, velocity) == 41 && offsetof(HighCmd, yawSpeed) == 49 &&
                  offsetof(HighCmd, led) == 53 && offsetof(HighCmd, wirelessRemote) == 65 &&
                  offsetof(HighCmd, reserve) == 105 && offsetof(HighCmd, crc) == 109,
              "HighCmd offsets of the reference");
static_assert(offsetof(HighState, mode) == 10 && offsetof(HighState, imu) == 11 &&
                  offsetof(HighState, position) == 64 && offsetof(HighState, velocity) == 76 &&
                  offsetof(HighState, yawSpeed) == 88 && offsetof(HighState, footPosition2Body) == 92 &&
                  offsetof(HighState, footSpeed2Body) == 140 && offsetof(HighState, footForce) == 188 &&
                  offsetof(HighState, wirelessRemote) == 196 && offsetof(HighState, reserve) == 236 &&
                  offsetof(HighState, crc) == 240,
              "HighState offsets of the reference");

// the vendor's CRC over whole 32-bit little-endian words: MSB first, polynomial 0x04C11DB7, start
// 0xFFFFFFFF, no reflection, no final xor
inline uint32_t crc32_words(const uint8_t* data, std::size_t words) {
  constexpr uint32_t kPolynomial = 0x04C11DB7u;
  uint32_t crc = 0xFFFFFFFFu;
  for (std::size_t w = 0; w < words; ++w) {
    const uint32_t word = static_cast<uint32_t>(data[4 * w]) | static_cast<uint32_t>(data[4 * w + 1]) << 8 |
                          static_cast<uint32_t>(data[4 * w + 2]) << 16 | static_cast<uint32_t>(data[4 * w + 3]) << 24;
    for (int bit = 31; bit >= 0; --bit) {
      const bool carry = (crc & 0x80000000u) != 0;
      crc <<= 1;
      if (carry) crc ^= kPolynomial;
      if ((word >> bit) & 1u) crc ^= kPolynomial;
    }
  }
  return crc;
}

// the CRC a frame of `length` bytes carries in its last 4 bytes: over the (length / 4) - 1 words
inline uint32_t frame_crc(const void* frame, std::size_t length) {
  return crc32_words(static_cast<const uint8_t*>(frame), length / 4 - 1);
}

// reads and writes the stored CRC (little-endian, the last 4 bytes)
inline uint32_t stored_crc(const void* frame, std::size_t length) {
  const uint8_t* p = static_cast<const uint8_t*>(frame) + length - 4;
  return static_cast<uint32_t>(p[0]) | static_cast<uint32_t>(p[1]) << 8 | static_cast<uint32_t>(p[2]) << 16 |
         static_cast<uint32_t>(p[3]) << 24;
}
inline void store_crc(void* frame, std::size_t length) {
  const uint32_t crc = frame_crc(frame, length);
  uint8_t* p = static_cast<uint8_t*>(frame) + length - 4;
  p[0] = static_cast<uint8_t>(crc);
  p[1] = static_cast<uint8_t>(crc >> 8);
  p[2] = static_cast<uint8_t>(crc >> 16);
  p[3] = static_cast<uint8_t>(crc >> 24);
}

}  // namespace UNITREE_LEGGED_SDK
