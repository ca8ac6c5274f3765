#!/usr/bin/env bash
# CI stage: the robot's build (docs/robot-build.md). Installs and cross-builds the static aarch64
# MC with its tests (scripts/build_robot.sh, which fails unless the program is static with no glibc
# symbol newer than 2.31), runs under qemu (ctest in build-aarch64: CMAKE_CROSSCOMPILING_EMULATOR)
# every aarch64 test that needs neither the simulator (not built there) nor a socket or real time,
# then the stacked pair with the aarch64 B under qemu standing the robot of an x86 A: the build
# machine's simulator build in build/ (CI's first stage; without it this last step is skipped).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/build_robot.sh"
cd "$root/build-aarch64"
start=$SECONDS
ctest --output-on-failure --timeout 600 -j2 -LE "sockets|realtime|process|aarch64" 2>&1 | tee ctest-qemu.log
echo "test_robot_build: the aarch64 tests under qemu: $((SECONDS - start)) s"
host_cerebellum="$root/build/src/cli/cerebellum"
if [[ -x "$host_cerebellum" ]] && "$host_cerebellum" --help | grep -q "^  sim .*simulated" &&
   ! "$host_cerebellum" --help | grep -q "not in this build"; then
  cmake -S "$root" -B "$root/build-aarch64" -DCEREBELLUM_STACK_A="$host_cerebellum" >/dev/null
  ctest --output-on-failure -L aarch64 2>&1 | tee ctest-stack.log
else
  echo "test_robot_build: no simulator build in build/ (scripts/build.sh): the stacked pair under qemu is not run"
fi
