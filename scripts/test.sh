#!/usr/bin/env bash
# Every test on a fresh machine: install dependencies, build everything, run ctest.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/install_deps.sh"
"$root/scripts/build.sh"
cd "$root/build"
ctest --output-on-failure --timeout 600 -j"$(nproc)"
