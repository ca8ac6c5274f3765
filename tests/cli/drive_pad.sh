#!/usr/bin/env bash
# Runs drive_pad.py against `cerebellum sim --speed 1` (real time), inside a private network
# namespace (scripts/netns_run.sh).
#   drive_pad.sh <cerebellum> <generated python types> <work dir>
set -euo pipefail
exe=$1
types=$2
work=$3
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
mkdir -p "$work"
cd "$work"
"$exe" sim --speed 1 --duration 90 > sim.log 2>&1 &
sim=$!
trap 'kill -9 $sim 2>/dev/null || true' EXIT
for _ in $(seq 300); do grep -q "cerebellum ready" sim.log && break; sleep 0.1; done
grep -q "cerebellum ready" sim.log || { cat sim.log; echo "drive_pad: the MC did not start"; exit 1; }
PYTHONPATH="$types" /usr/bin/python3 "$here/drive_pad.py" "$exe" "$here/drive_walk_unplug.pad" "$here/drive_walk_damp.pad"
