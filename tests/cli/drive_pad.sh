#!/usr/bin/env bash
# Runs drive_pad.py against `cerebellum sim --speed 1` (real time), inside a private network
# namespace (scripts/netns_run.sh).
#   drive_pad.sh <cerebellum> <generated python types> <work dir>
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
source "$here/../seed_support.sh"
exe=$1
types=$2
work=$3
mkdir -p "$work"
cd "$work"
start_sim sim.log "$exe" sim --speed 1 --duration 90
trap 'kill -9 $sim_pid 2>/dev/null || true' EXIT
PYTHONPATH="$types" /usr/bin/python3 "$here/drive_pad.py" "$exe" "$here/drive_walk_unplug.pad" "$here/drive_walk_damp.pad" \
  "$here/drive_damp_every_mode.pad" "$here/drive_pose.pad"
