#!/usr/bin/env bash
# The MC under two clients flooding at once (valid robot_control_cmd on LCM and valid HighCmd on
# UDP, each as fast as one thread sends): the loop keeps ticking (robot time keeps pace with the
# wall clock within a loaded machine's margin) and SIGINT stops the MC within 1 s, mid-flood.
# Runs inside a private network namespace (scripts/netns_run.sh).
#   flood_liveness.sh <cerebellum> <flood_clients> <work dir>
set -euo pipefail
exe=$1
flood=$2
work=$3
mkdir -p "$work"
cd "$work"
rm -f sim.log
"$exe" sim --speed 1 --duration 120 > sim.log 2>&1 &
sim=$!
trap 'kill -9 $sim 2>/dev/null || true' EXIT
for _ in $(seq 300); do grep -q "cerebellum ready" sim.log && break; sleep 0.1; done
grep -q "cerebellum ready" sim.log || { cat sim.log; echo "flood_liveness: the MC did not start"; exit 1; }
# the newest robot time the console reporter printed (once a second of robot time)
robot_time() { grep -o '^t= *[0-9.]*' sim.log | tail -1 | tr -dc '0-9.'; }
sleep 1.5
before=$(robot_time)
"$flood" "udpm://239.255.76.67:7671?ttl=0" 8082 8
after=$(robot_time)
echo "flood_liveness: robot time ${before} s -> ${after} s over an 8 s flood"
# a loop that hung prints nothing more; one that keeps ticking advances about 8 s (4 on a loaded machine)
awk -v a="$before" -v b="$after" 'BEGIN { exit !(b - a >= 4.0) }' ||
  { tail -40 sim.log; echo "flood_liveness: the loop did not keep ticking under the flood"; exit 1; }
# SIGINT in the middle of a second flood
"$flood" "udpm://239.255.76.67:7671?ttl=0" 8082 6 > /dev/null &
flooder=$!
sleep 2
start=$(date +%s.%N)
kill -INT $sim
status=0
wait $sim || status=$?
stop_s=$(awk -v s="$start" -v e="$(date +%s.%N)" 'BEGIN { printf "%.2f", e - s }')
trap - EXIT
wait $flooder || true
echo "flood_liveness: SIGINT to exit ${stop_s} s, exit status ${status}"
grep -E "^(highlevel|aliengo): (robot_control_cmd|HighCmd) [0-9]+ received" sim.log || true
[[ $status -eq 0 ]] || { tail -40 sim.log; echo "flood_liveness: the MC exited with $status"; exit 1; }
awk -v s="$stop_s" 'BEGIN { exit !(s <= 1.0) }' || { echo "flood_liveness: SIGINT took ${stop_s} s (limit 1 s)"; exit 1; }
echo "flood_liveness: ok"
