#pragma once
// generic field helpers over LcmReference<Msg>::fields: fill with seeded random values,
// compare, encode, and an independent big-endian encoding built from the reference field list

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <random>
#include <string>
#include <string_view>
#include <tuple>
#include <type_traits>
#include <vector>

#include "lcm/lcm_type_reference.hpp"

namespace cerebellum::test {

using Bytes = std::vector<std::uint8_t>;

template <class Msg, class F>
void for_each_member(F&& f) {
  std::apply([&](auto... member) { (f(member), ...); }, LcmReference<Msg>::fields);
}

// fill: floats in [-100, 100), integers over their full range, printable text
template <class T>
requires std::is_arithmetic_v<T>
void fill_value(T& value, std::mt19937& rng) {
  if constexpr (std::is_floating_point_v<T>) {
    value = std::uniform_real_distribution<T>(-100, 100)(rng);
  } else {
    std::uniform_int_distribution<std::int64_t> dist(std::numeric_limits<T>::min(), std::numeric_limits<T>::max());
    value = static_cast<T>(dist(rng));
  }
}

template <class T, std::size_t N>
void fill_value(T (&values)[N], std::mt19937& rng) {
  for (T& value : values) fill_value(value, rng);
}

inline void fill_value(std::string& text, std::mt19937& rng) {
  std::uniform_int_distribution<std::size_t> length(1, 300);
  std::uniform_int_distribution<int> character(' ', '~');
  text.resize(length(rng));
  for (char& c : text) c = static_cast<char>(character(rng));
  text.front() = '\n';
}

template <class Msg>
Msg random_message(std::uint32_t seed) {
  std::mt19937 rng(seed);
  Msg msg{};
  for_each_member<Msg>([&](auto member) { fill_value(msg.*member, rng); });
  return msg;
}

// compare field by field (exact: a round trip must not change a bit)
template <class T>
bool same_value(const T& a, const T& b) {
  return a == b;
}

template <class T, std::size_t N>
bool same_value(const T (&a)[N], const T (&b)[N]) {
  return std::equal(a, a + N, b);
}

template <class Msg>
void expect_same_fields(const Msg& expected, const Msg& actual) {
  std::size_t index = 0;
  for_each_member<Msg>([&](auto member) {
    EXPECT_TRUE(same_value(expected.*member, actual.*member)) << Msg::getTypeName() << " field #" << index;
    ++index;
  });
}

// encode with the generated code
template <class Msg>
Bytes encode_message(const Msg& msg) {
  Bytes buffer(static_cast<std::size_t>(msg.getEncodedSize()));
  const int written = msg.encode(buffer.data(), 0, static_cast<int>(buffer.size()));
  EXPECT_EQ(written, static_cast<int>(buffer.size()));
  return buffer;
}

inline Bytes bytes_from_hex(std::string_view hex) {
  Bytes bytes;
  for (std::size_t i = 0; i + 1 < hex.size(); i += 2) {
    bytes.push_back(static_cast<std::uint8_t>(std::stoul(std::string(hex.substr(i, 2)), nullptr, 16)));
  }
  return bytes;
}

inline std::string hex_from_bytes(const Bytes& bytes) {
  static constexpr char kDigits[] = "0123456789abcdef";
  std::string hex;
  for (std::uint8_t b : bytes) {
    hex.push_back(kDigits[b >> 4]);
    hex.push_back(kDigits[b & 0x0f]);
  }
  return hex;
}

// independent encoder: fingerprint, then every field big-endian in reference order;
// strings as int32 length (including the nul), the text, a nul
class BigEndianWriter {
 public:
  template <class T>
  requires std::is_arithmetic_v<T>
  void put(T value) {
    auto raw = std::bit_cast<std::array<std::uint8_t, sizeof(T)>>(value);
    if constexpr (std::endian::native == std::endian::little) std::reverse(raw.begin(), raw.end());
    bytes_.insert(bytes_.end(), raw.begin(), raw.end());
  }

  template <class T, std::size_t N>
  void put(const T (&values)[N]) {
    for (const T& value : values) put(value);
  }

  void put(const std::string& text) {
    put(static_cast<std::int32_t>(text.size() + 1));
    bytes_.insert(bytes_.end(), text.begin(), text.end());
    bytes_.push_back(0);
  }

  void put_raw(const Bytes& raw) { bytes_.insert(bytes_.end(), raw.begin(), raw.end()); }

  const Bytes& bytes() const { return bytes_; }

 private:
  Bytes bytes_;
};

template <class Msg>
Bytes reference_encoding(const Msg& msg) {
  BigEndianWriter writer;
  writer.put_raw(bytes_from_hex(LcmReference<Msg>::fingerprint_hex));
  for_each_member<Msg>([&](auto member) { writer.put(msg.*member); });
  return writer.bytes();
}

}  // namespace cerebellum::test
