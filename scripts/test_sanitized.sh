#!/usr/bin/env bash
# The sanitized stage of CI: builds with clang + ASan + UBSan (scripts/build_sanitized.sh), runs
# the tests that do not run programs against the clock (labels demo, sockets, process, tools,
# install, realtime, slurm left out: they are real-time end-to-end runs the Release stage covers (slurm:
# the sweep through a single-node Slurm started by the test), and a
# sanitized MC falls behind the clock under load (a client's heartbeats then look late); seeds:
# long seeded sweeps of the simulation, and long: the longest lockstep runs (over half a minute of
# simulation each, about a minute sanitized); the Release stage runs both, and the code paths they
# take are covered here by the short tests), then a short run
# of every libFuzzer program. Usage: scripts/test_sanitized.sh [fuzz seconds per target, default 5]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
fuzz_seconds=${1:-5}
# the labels left out: their test programs are not compiled either (tests/CMakeLists.txt)
left_out="demo;sockets;process;tools;install;seeds;long;realtime;slurm"
"$root/scripts/install_deps.sh"
CEREBELLUM_TEST_LABELS_LEFT_OUT="$left_out" "$root/scripts/build_sanitized.sh"
cd "$root/build-sanitize"
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
ctest --output-on-failure --timeout 900 -j"$(nproc)" -LE "${left_out//;/|}" 2>&1 | tee ctest.log
status=${PIPESTATUS[0]}
[[ $status -eq 0 ]] || exit "$status"
FUZZ_SEED=1 "$root/scripts/fuzz.sh" "$fuzz_seconds"
