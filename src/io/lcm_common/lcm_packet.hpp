// Raw LCM packets checked before they are decoded, so that malformed ones are told apart and
// counted instead of decoded into garbage: the 8-byte fingerprint, then the exact size.
#pragma once

#include <cstddef>
#include <cstdint>

namespace cerebellum {

enum class WireDecode {
  Ok,
  WrongFingerprint,  // the first 8 bytes are not the type's hash
  Truncated,         // shorter than the message (or than its declared string length)
  Oversized,         // longer than the message (or a string above the size limit)
};
const char* to_string(WireDecode result);

inline constexpr std::size_t kLcmFingerprintBytes = 8;

// true when the packet starts with the big-endian 64-bit hash
bool has_fingerprint(const void* data, std::size_t size, std::int64_t hash);

// a message of a fixed-size LCM type (no strings or variable arrays): fingerprint, then exactly
// its encoded size, then LCM's own decode
template <typename Message>
WireDecode decode_fixed_size(const void* data, std::size_t size, Message& message) {
  static const int kEncodedSize = Message{}.getEncodedSize();
  if (size < kLcmFingerprintBytes) return WireDecode::Truncated;
  if (!has_fingerprint(data, size, Message::getHash())) return WireDecode::WrongFingerprint;
  if (size < static_cast<std::size_t>(kEncodedSize)) return WireDecode::Truncated;
  if (size > static_cast<std::size_t>(kEncodedSize)) return WireDecode::Oversized;
  if (message.decode(data, 0, kEncodedSize) != kEncodedSize) return WireDecode::Truncated;
  return WireDecode::Ok;
}

}  // namespace cerebellum
