// One counter of an adapter, named once: a field of the adapter's counters struct that its thread
// increments and any thread reads (relaxed: counters order nothing). Copying a counters struct
// takes a snapshot, so an adapter keeps one struct of Counts and hands out copies, instead of
// naming each counter again as an atomic and again in a copy.
#pragma once

#include <atomic>
#include <cstdint>
#include <ostream>

namespace cerebellum {

class Count {
 public:
  Count() = default;
  Count(std::uint64_t value) : value_(value) {}  // NOLINT: a snapshot's field from a plain figure
  Count(const Count& other) : value_(other.load()) {}
  Count& operator=(const Count& other) {
    value_.store(other.load(), std::memory_order_relaxed);
    return *this;
  }
  Count& operator=(std::uint64_t value) {
    value_.store(value, std::memory_order_relaxed);
    return *this;
  }

  void add(std::uint64_t n = 1) { value_.fetch_add(n, std::memory_order_relaxed); }
  std::uint64_t load() const { return value_.load(std::memory_order_relaxed); }
  operator std::uint64_t() const { return load(); }  // NOLINT: reads as the number it counts

 private:
  std::atomic<std::uint64_t> value_{0};
};

inline std::ostream& operator<<(std::ostream& out, const Count& count) { return out << count.load(); }

}  // namespace cerebellum
