#!/usr/bin/env bash
# The main job on a fresh machine: install dependencies, build, then run the demo: the MC on the
# simulated CyberDog2, driven through the real LCM high-level interface by a demo client (stand,
# pose, walk a square, turn, lie down), inside a private network namespace. Writes a video, a
# telemetry log and plots under build/demo/ and prints their paths.
#   scripts/demo.sh [--short]      (--short: a smaller tour, used by the tests)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/install_deps.sh"
"$root/scripts/build.sh" cerebellum cerebellum_demo_tour
exec "$root/scripts/netns_run.sh" "$root/scripts/demo_run.sh" "$@"
