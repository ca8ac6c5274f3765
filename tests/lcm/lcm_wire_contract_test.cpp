// every generated type against the reference table: fingerprint, size, field order on the wire
#include <gtest/gtest.h>

#include <cstdint>

#include "lcm/lcm_message_fields.hpp"
#include "lcm/lcm_type_reference.hpp"

namespace cerebellum::test {
namespace {

template <class Msg>
class LcmWireContract : public ::testing::Test {};
TYPED_TEST_SUITE(LcmWireContract, AllLcmTypes, LcmTypeName);

TYPED_TEST(LcmWireContract, FirstEightBytesAreTheReferenceFingerprint) {
  const Bytes encoded = encode_message(TypeParam{});
  const Bytes fingerprint = bytes_from_hex(LcmReference<TypeParam>::fingerprint_hex);
  ASSERT_EQ(fingerprint.size(), 8u);
  ASSERT_GE(encoded.size(), 8u);
  EXPECT_EQ(hex_from_bytes(Bytes(encoded.begin(), encoded.begin() + 8)), LcmReference<TypeParam>::fingerprint_hex);

  std::uint64_t fingerprint_value = 0;
  for (std::uint8_t b : fingerprint) fingerprint_value = (fingerprint_value << 8) | b;
  EXPECT_EQ(static_cast<std::uint64_t>(TypeParam::getHash()), fingerprint_value);
}

TYPED_TEST(LcmWireContract, EncodedSizeIsTheReferenceSize) {
  for (std::uint32_t seed : {1u, 2u, 3u}) {
    const TypeParam msg = random_message<TypeParam>(seed);
    const std::size_t expected = reference_encoded_size(msg);
    EXPECT_EQ(static_cast<std::size_t>(msg.getEncodedSize()), expected);
    EXPECT_EQ(encode_message(msg).size(), expected);
    // the field list transcribed from the table adds up to the table's size as well
    EXPECT_EQ(reference_encoding(msg).size(), expected);
  }
}

TYPED_TEST(LcmWireContract, EncodingIsBigEndianFieldsInReferenceOrder) {
  for (std::uint32_t seed : {11u, 12u, 13u}) {
    const TypeParam msg = random_message<TypeParam>(seed);
    EXPECT_EQ(hex_from_bytes(encode_message(msg)), hex_from_bytes(reference_encoding(msg))) << "seed " << seed;
  }
}

TEST(LcmWireContract, FileSendSizeCountsLengthTextAndNul) {
  file_send_lcmt msg;
  msg.data = "# Gait Def\n";
  EXPECT_EQ(msg.getEncodedSize(), 8 + 4 + 11 + 1);
  msg.data.clear();
  EXPECT_EQ(msg.getEncodedSize(), 8 + 4 + 0 + 1);
}

}  // namespace
}  // namespace cerebellum::test
