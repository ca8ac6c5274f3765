// Waiting in the socket tests for what another thread or process does: poll a condition on the
// wall clock, the timeout only bounding a failing test.
#pragma once

#include <chrono>
#include <thread>

namespace cerebellum {

// polls condition every 2 ms of wall time; false when it is still not true after timeout_s
template <typename Condition>
bool eventually(Condition condition, double timeout_s = 10.0) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
  while (!condition()) {
    if (std::chrono::steady_clock::now() > deadline) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  return true;
}

}  // namespace cerebellum
