#!/usr/bin/env bash
# The main job on a fresh machine: install dependencies, build, and run the MC on the simulated
# CyberDog2 (it stands up and holds, printing height and joint state once a second).
#   scripts/demo.sh [cerebellum sim options]   (default: --speed 1 --duration 10)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/install_deps.sh"
"$root/scripts/build.sh" cerebellum
args=("$@")
[[ ${#args[@]} -gt 0 ]] || args=(--speed 1 --duration 10)
exec "$root/scripts/netns_run.sh" "$root/build/src/app/cerebellum" sim --config "$root/config/cerebellum.yaml" "${args[@]}"
