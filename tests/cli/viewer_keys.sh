#!/usr/bin/env bash
# Runs viewer_keys.py against `cerebellum sim --viewer --speed 1` (real time) on a virtual display,
# inside a private network namespace (scripts/netns_run.sh): the sim's window takes the keys that
# xdotool types into it through the X server (XTEST), as a person's keyboard would.
#   viewer_keys.sh <cerebellum> <generated python types> <work dir>
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
exe=$1
types=$2
work=$3
mkdir -p "$work"
cd "$work"
# the whole run on one virtual display: the window and xdotool must share it
if [[ -z "${VIEWER_KEYS_ON_DISPLAY:-}" ]]; then
  VIEWER_KEYS_ON_DISPLAY=1 exec xvfb-run -a -s "-screen 0 1280x800x24" "$0" "$@"
fi
source "$here/../seed_support.sh"
start_sim sim.log "$exe" sim --viewer --speed 1 --duration 70
trap 'kill -9 $sim_pid 2>/dev/null || true' EXIT
PYTHONPATH="$types" /usr/bin/python3 "$here/viewer_keys.py"
