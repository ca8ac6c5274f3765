#!/usr/bin/env bash
# The stacked pair's figures as MC B itself reports them (issue 42): for each backend, the pair
# (scripts/stack.sh) stands the robot and walks it at 0.5 m/s for SECONDS while `cerebellum status
# --diagnostics` records B's once-a-second mc_diagnostics; then one line per backend: B's loop
# period (the median of the seconds' p50, the largest p99 and max), the state's age when read, the
# command-to-state round trip where the link shows it (the ZsiBot's flags), and the link's losses,
# refused states and late frames. The motor SDK echoes nothing: a third listener times its frames
# on the wire (bench/stack_wire_tap.py: each command to the first state after it, a lower bound of
# the round trip, and each state to B's next command). Real time on this machine: run it with
# nothing else running.
#   bench/stack_figures.sh [SECONDS]     (default 30)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
seconds=${1:-30}
exe="$root/build/src/cli/cerebellum"
[[ -x "$exe" ]] || { echo "stack_figures.sh: build first (scripts/build.sh)" >&2; exit 2; }
out="$root/build/bench/results/stack_figures"
mkdir -p "$out"
types="$root/build/lcm/python"
for robot in cyberdog2-motor-sdk zsibot-shm; do
  # the motor SDK's link is also timed on the wire by a third listener (bench/stack_wire_tap.py)
  tap=":"
  [[ $robot == cyberdog2-motor-sdk ]] &&
    tap="PYTHONPATH='$types' /usr/bin/python3 '$root/bench/stack_wire_tap.py' $seconds > '$out/$robot/wire.log' 2>&1"
  "$root/scripts/stack.sh" --robot "$robot" --cerebellum "$exe" --logs "$out/$robot" bash -c "
    '$exe' cmd stand --ttl 0 --hold 0 > /dev/null
    '$exe' cmd walk --ttl 0 --vx 0.5 --duration $((seconds + 2)) --hold 0 > /dev/null &
    $tap &
    timeout -s INT $seconds '$exe' status --ttl 0 --diagnostics --rate 0.2 > '$out/$robot/status.log' || true
    wait" > "$out/$robot.txt" 2>&1 || { cat "$out/$robot.txt"; exit 1; }
  [[ -f "$out/$robot/wire.log" ]] && sed "s/^/$robot: /" "$out/$robot/wire.log"
  /usr/bin/python3 - "$robot" "$out/$robot/status.log" <<'PY'
import re
import statistics
import sys

robot, path = sys.argv[1], sys.argv[2]
triple = r"p50 ([0-9.]+) / p99 ([0-9.]+) / max ([0-9.]+) ms"
rows = {"loop period": [], "state age": [], "round trip": []}
last = None
for line in open(path):
    if not line.startswith("mc: "):
        continue
    for name in rows:
        m = re.search(name + " " + triple, line)
        if m:
            rows[name].append(tuple(float(v) for v in m.groups()))
    last = line
if last is None:
    sys.exit("stack_figures: no mc_diagnostics line from B (%s)" % path)
def summary(name):
    values = rows[name]
    if not values:
        return "%s: not measured" % name
    return "%s p50 %.2f / p99 %.2f / max %.2f ms" % (
        name, statistics.median(v[0] for v in values), max(v[1] for v in values), max(v[2] for v in values))
counts = re.search(r"(\d+) losses, (\d+) states refused, (\d+) frames late", last)
print("%s: %d s of B's figures; %s; %s; %s; %s losses, %s states refused, %s frames late"
      % (robot, len(rows["loop period"]), summary("loop period"), summary("state age"), summary("round trip"),
         *counts.groups()))
PY
done
