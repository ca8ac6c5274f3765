#include "io/lcm_common/lcm_packet.hpp"

namespace cerebellum {

const char* to_string(WireDecode result) {
  switch (result) {
    case WireDecode::Ok: return "ok";
    case WireDecode::WrongFingerprint: return "wrong fingerprint";
    case WireDecode::Truncated: return "truncated";
    case WireDecode::Oversized: return "oversized";
  }
  return "?";
}

bool has_fingerprint(const void* data, std::size_t size, std::int64_t hash) {
  if (size < kLcmFingerprintBytes) return false;
  const auto* bytes = static_cast<const std::uint8_t*>(data);
  std::uint64_t value = 0;
  for (std::size_t i = 0; i < kLcmFingerprintBytes; ++i) value = (value << 8) | bytes[i];
  return value == static_cast<std::uint64_t>(hash);
}

}  // namespace cerebellum
