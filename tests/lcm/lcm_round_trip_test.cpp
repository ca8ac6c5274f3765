// encode then decode restores every field; short buffers and foreign fingerprints are refused
#include <gtest/gtest.h>

#include <cstdint>

#include "lcm/lcm_message_fields.hpp"
#include "lcm/lcm_type_reference.hpp"

namespace cerebellum::test {
namespace {

template <class Msg>
class LcmRoundTrip : public ::testing::Test {};
TYPED_TEST_SUITE(LcmRoundTrip, AllLcmTypes, LcmTypeName);

TYPED_TEST(LcmRoundTrip, DecodeRestoresEveryField) {
  for (std::uint32_t seed : {21u, 22u, 23u, 24u}) {
    const TypeParam sent = random_message<TypeParam>(seed);
    const Bytes encoded = encode_message(sent);
    TypeParam received{};
    EXPECT_EQ(received.decode(encoded.data(), 0, static_cast<int>(encoded.size())), static_cast<int>(encoded.size()));
    expect_same_fields(sent, received);
  }
}

TYPED_TEST(LcmRoundTrip, DecodeAtAnOffsetReadsFromThere) {
  const TypeParam sent = random_message<TypeParam>(31);
  const Bytes encoded = encode_message(sent);
  Bytes padded(5, 0xAB);
  padded.insert(padded.end(), encoded.begin(), encoded.end());
  TypeParam received{};
  EXPECT_EQ(received.decode(padded.data(), 5, static_cast<int>(encoded.size())), static_cast<int>(encoded.size()));
  expect_same_fields(sent, received);
}

TYPED_TEST(LcmRoundTrip, EveryTruncatedBufferIsRefused) {
  const Bytes encoded = encode_message(random_message<TypeParam>(41));
  for (std::size_t length = 0; length < encoded.size(); ++length) {
    TypeParam received{};
    EXPECT_LT(received.decode(encoded.data(), 0, static_cast<int>(length)), 0)
        << "length " << length << " of " << encoded.size();
  }
}

TYPED_TEST(LcmRoundTrip, AnyChangedFingerprintByteIsRefused) {
  const Bytes encoded = encode_message(random_message<TypeParam>(51));
  for (std::size_t i = 0; i < 8; ++i) {
    Bytes corrupted = encoded;
    corrupted[i] ^= static_cast<std::uint8_t>(1u << (i % 8));
    TypeParam received{};
    EXPECT_LT(received.decode(corrupted.data(), 0, static_cast<int>(corrupted.size())), 0) << "byte " << i;
  }
}

TEST(LcmRoundTrip, AnotherTypesMessageIsRefused) {
  const Bytes command = encode_message(random_message<robot_control_cmd_lcmt>(61));
  robot_control_response_lcmt response{};
  EXPECT_LT(response.decode(command.data(), 0, static_cast<int>(command.size())), 0);
}

}  // namespace
}  // namespace cerebellum::test
