// Builds LCM packets by hand, big-endian, from the reference field lists: an encoder independent
// of lcm-gen's, for decoding tests.
#pragma once

#include <bit>
#include <cstdint>
#include <string>
#include <vector>

namespace cerebellum::test {

class BigEndianWriter {
 public:
  BigEndianWriter& u64(std::uint64_t v) { return bytes_of(v, 8); }
  BigEndianWriter& i32(std::int32_t v) { return bytes_of(static_cast<std::uint32_t>(v), 4); }
  BigEndianWriter& i16(std::int16_t v) { return bytes_of(static_cast<std::uint16_t>(v), 2); }
  BigEndianWriter& i8(std::int8_t v) { return bytes_of(static_cast<std::uint8_t>(v), 1); }
  BigEndianWriter& f32(float v) { return bytes_of(std::bit_cast<std::uint32_t>(v), 4); }
  BigEndianWriter& raw(const std::string& text) {
    bytes_.insert(bytes_.end(), text.begin(), text.end());
    return *this;
  }
  const std::vector<std::uint8_t>& bytes() const { return bytes_; }

 private:
  BigEndianWriter& bytes_of(std::uint64_t v, int count) {
    for (int i = count - 1; i >= 0; --i) bytes_.push_back(static_cast<std::uint8_t>(v >> (8 * i)));
    return *this;
  }
  std::vector<std::uint8_t> bytes_;
};

// wire fingerprints from the reference (shared/reference/cyberdog2-highlevel.md, section 2)
inline constexpr std::uint64_t kRobotControlCmdHash = 0x8ed6c3c52d5f2deaull;
inline constexpr std::uint64_t kRobotControlResponseHash = 0x90bb53042ddb518eull;
inline constexpr std::uint64_t kFileSendHash = 0x21bf37099b9d5e15ull;
inline constexpr std::uint64_t kFileRecvHash = 0xececa67e3eda6d7dull;
inline constexpr std::uint64_t kLocalizationHash = 0xfc48de06e344fb12ull;
inline constexpr std::uint64_t kDangerStatesHash = 0x3833e1f8ac8e5548ull;

// a robot_control_cmd whose float fields count up from first_float in steps of 0.25
inline std::vector<std::uint8_t> robot_control_cmd_packet(std::int8_t mode, std::int8_t gait_id, std::int8_t contact,
                                                          std::int8_t life_count, float first_float, std::int32_t value,
                                                          std::int32_t duration) {
  BigEndianWriter w;
  w.u64(kRobotControlCmdHash).i8(mode).i8(gait_id).i8(contact).i8(life_count);
  // vel_des[3], rpy_des[3], pos_des[3], acc_des[6], ctrl_point[3], foot_pose[6], step_height[2]
  for (int i = 0; i < 26; ++i) w.f32(first_float + 0.25f * static_cast<float>(i));
  w.i32(value).i32(duration);
  return w.bytes();
}

inline std::vector<std::uint8_t> file_send_packet(const std::string& text) {
  BigEndianWriter w;
  w.u64(kFileSendHash).i32(static_cast<std::int32_t>(text.size() + 1)).raw(text).i8(0);
  return w.bytes();
}

}  // namespace cerebellum::test
