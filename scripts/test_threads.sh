#!/usr/bin/env bash
# The ThreadSanitizer stage of CI: builds with clang + TSan into ./build-tsan only the test
# programs labelled `threads` (CEREBELLUM_TEST_LABELS_ONLY: the ones that start threads beside the
# loop: the machine's per-client inboxes under two flooding threads, every adapter with its
# thread, the shared memory, the MPC worker of the walking tests, the recorders' writers) and runs
# them; a data race, a lock-order inversion or a thread leak fails the stage (halt_on_error).
# Usage: scripts/test_threads.sh
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/install_deps.sh"
flags="-O1 -gline-tables-only -fsanitize=thread -fno-omit-frame-pointer"
# the configure output goes to a log beside the build tree (quiet CI output; kept out of git)
CC=clang CXX=clang++ cmake -S "$root" -B "$root/build-tsan" -DCMAKE_BUILD_TYPE=ThreadSanitize \
  -DCMAKE_C_FLAGS="$flags" -DCMAKE_CXX_FLAGS="$flags" \
  -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=thread" -DCMAKE_SHARED_LINKER_FLAGS="-fsanitize=thread" \
  -DCEREBELLUM_SANITIZED=ON -DCEREBELLUM_BUILD_BENCH=OFF -DCEREBELLUM_TEST_LABELS_ONLY=threads \
  > "$root/build-tsan.configure.log" || { cat "$root/build-tsan.configure.log"; exit 1; }
cmake --build "$root/build-tsan" -j"$(nproc)"
cd "$root/build-tsan"
# suppressions: only glib's lazily allocated mutex, which TSan cannot see published (scripts/tsan.supp)
export TSAN_OPTIONS="halt_on_error=1 second_deadlock_stack=1 report_thread_leaks=1 suppressions=$root/scripts/tsan.supp"
set +e
ctest --output-on-failure --timeout 900 -j"$(nproc)" -L threads 2>&1 | tee ctest.log
status=${PIPESTATUS[0]}
set -e
# a stage that ran nothing proves nothing
if ! grep -qE '^100% tests passed|tests passed, [0-9]+ tests failed' ctest.log; then
  echo "test_threads.sh: ctest ran no test"
  exit 1
fi
exit "$status"
