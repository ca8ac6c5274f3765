#!/usr/bin/env bash
# Configures and builds cerebellum with clang, AddressSanitizer and UndefinedBehaviorSanitizer
# (and libFuzzer's coverage instrumentation) into ./build-sanitize: the tests and the libFuzzer
# programs of tests/fuzz (docs/fuzzing.md). Usage: scripts/build_sanitized.sh [cmake targets...]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
# -O1 and line tables only (build type Sanitize adds no flags of its own): what the sanitizers'
# documentation recommends, and quicker to compile than RelWithDebInfo (-O2 -g)
flags="-O1 -gline-tables-only -fsanitize=address,undefined,fuzzer-no-link -fno-sanitize-recover=undefined -fno-omit-frame-pointer"
# the configure output goes to a log beside the build tree (quiet CI output; kept out of git)
CC=clang CXX=clang++ cmake -S "$root" -B "$root/build-sanitize" -DCMAKE_BUILD_TYPE=Sanitize \
  -DCMAKE_C_FLAGS="$flags" -DCMAKE_CXX_FLAGS="$flags" \
  -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" -DCMAKE_SHARED_LINKER_FLAGS="-fsanitize=address,undefined" \
  -DCEREBELLUM_FUZZ=ON -DCEREBELLUM_SANITIZED=ON -DCEREBELLUM_BUILD_BENCH=OFF \
  -DCEREBELLUM_TEST_LABELS_LEFT_OUT="${CEREBELLUM_TEST_LABELS_LEFT_OUT:-}" > "$root/build-sanitize.configure.log" ||
  { cat "$root/build-sanitize.configure.log"; exit 1; }
if [[ $# -gt 0 ]]; then
  cmake --build "$root/build-sanitize" -j"$(nproc)" --target "$@"
else
  cmake --build "$root/build-sanitize" -j"$(nproc)"
fi
