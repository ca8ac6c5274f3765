#!/usr/bin/env bash
# Configures and builds cerebellum (Release) into ./build. Usage: scripts/build.sh [cmake targets...]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cmake -S "$root" -B "$root/build" -DCMAKE_BUILD_TYPE=Release
if [[ $# -gt 0 ]]; then
  for target in "$@"; do cmake --build "$root/build" --target "$target" -j"$(nproc)"; done
else
  cmake --build "$root/build" -j"$(nproc)"
fi
