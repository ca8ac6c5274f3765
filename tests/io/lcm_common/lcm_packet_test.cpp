#include "io/lcm_common/lcm_packet.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "localization_lcmt.hpp"

namespace cerebellum {
namespace {

using Bytes = std::vector<std::uint8_t>;

Bytes encoded(const localization_lcmt& message) {
  Bytes bytes(static_cast<std::size_t>(message.getEncodedSize()));
  message.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
  return bytes;
}

TEST(LcmPacket, TheFingerprintIsTheTypesHashInBigEndianOrder) {
  const Bytes bytes = encoded(localization_lcmt{});
  const auto hash = static_cast<std::uint64_t>(localization_lcmt::getHash());
  for (std::size_t i = 0; i < 8; ++i) EXPECT_EQ(bytes[i], static_cast<std::uint8_t>(hash >> (56 - 8 * i)));
  EXPECT_TRUE(has_fingerprint(bytes.data(), bytes.size(), localization_lcmt::getHash()));
  EXPECT_FALSE(has_fingerprint(bytes.data(), 7, localization_lcmt::getHash()));
  EXPECT_FALSE(has_fingerprint(bytes.data(), bytes.size(), localization_lcmt::getHash() + 1));
}

TEST(LcmPacket, AFixedSizeMessageDecodesOnlyAtExactlyItsSize) {
  localization_lcmt sent{};
  sent.xyz[0] = 1.5f;
  sent.rpy[2] = -0.25f;
  Bytes bytes = encoded(sent);
  localization_lcmt received{};
  ASSERT_EQ(decode_fixed_size(bytes.data(), bytes.size(), received), WireDecode::Ok);
  EXPECT_EQ(received.xyz[0], 1.5f);
  EXPECT_EQ(received.rpy[2], -0.25f);
  EXPECT_EQ(decode_fixed_size(bytes.data(), 0, received), WireDecode::Truncated);
  EXPECT_EQ(decode_fixed_size(bytes.data(), bytes.size() - 1, received), WireDecode::Truncated);
  Bytes longer = bytes;
  longer.push_back(0);
  EXPECT_EQ(decode_fixed_size(longer.data(), longer.size(), received), WireDecode::Oversized);
  bytes[3] ^= 0x40;
  EXPECT_EQ(decode_fixed_size(bytes.data(), bytes.size(), received), WireDecode::WrongFingerprint);
}

}  // namespace
}  // namespace cerebellum
