// One fuzz target: feed arbitrary bytes to one decoder of client input and check what must hold
// whatever the bytes (no crash, no hang, a refusal or a result whose numbers are finite). Built
// twice: with libFuzzer (clang, CEREBELLUM_FUZZ=ON) and, in every build, with replay_main.cpp,
// which runs the target's seed corpus as a test.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstdlib>

// the property of a target failed: abort, so both libFuzzer and the replay test report it
#define FUZZ_CHECK(condition)                                                              \
  do {                                                                                     \
    if (!(condition)) {                                                                    \
      __builtin_printf("fuzz check failed: %s (%s:%d)\n", #condition, __FILE__, __LINE__); \
      std::abort();                                                                        \
    }                                                                                      \
  } while (0)

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);
