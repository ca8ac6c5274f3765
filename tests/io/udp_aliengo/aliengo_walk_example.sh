#!/usr/bin/env bash
# The AlienGo walk example (examples/aliengo), unchanged, against `cerebellum sim` at the vendor's
# robot address 192.168.123.220:8082 (on the loopback of a private network namespace: run through
# scripts/netns_run.sh). Judged on the simulation's ground truth: the example's last stage walks
# back to (0, 0) of the sport frame and stands (the sim stops while the silent client's robot
# still stands: docs/aliengo-udp.md).
# usage: aliengo_walk_example.sh <cerebellum> <aliengo_walk> <work dir> <generated python types dir>
set -uo pipefail
source "$(dirname "$0")/../../seed_support.sh"
cerebellum=$1 example=$2 work=$3 python_types=$4
rm -rf "$work" && mkdir -p "$work"
printf 'aliengo:\n  bind_address: 192.168.123.220\n' > "$work/sim.yaml"
start_truth_watch "$work/truth.log" "$python_types"
# the example's 66 s timeline counts its own 2 ms loop, which a loaded machine stretches (one CI-like
# run counted 29,567 loops while the MC ran 69 s and ended mid-walk): the MC runs until the example
# has finished, then 1 s more, within the 2 s the robot stands after the last HighCmd
start_sim "$work/sim.log" "$cerebellum" sim --speed 1 --duration 200 --config "$work/sim.yaml" \
  --telemetry "$work/telemetry.csv" --telemetry-rate 50
sim=$sim_pid
sleep 1
"$example" 192.168.123.220 > "$work/example.log" 2>&1
example_status=$?
sleep 1
kill -INT "$sim"
wait "$sim"
sim_status=$?
wait "$truth_pid"
echo "--- example output"
cat "$work/example.log"
echo "--- MC log"
grep -v '^    ' "$work/sim.log" | grep -v '^t=' | head -40
fail=0
[[ $sim_status -eq 0 ]] || { echo "WRONG: cerebellum sim exited with $sim_status"; fail=1; }
[[ $example_status -eq 0 ]] || { echo "WRONG: the example exited with $example_status"; fail=1; }
received=$(sed -n 's/.*HighState received \([0-9]*\).*/\1/p' "$work/example.log")
if [[ -z "$received" || "$received" -lt 25000 ]]; then
  echo "WRONG: the example received '${received}' HighState frames in its 33,000 loops of 2 ms"; fail=1
fi
grep -q "aliengo: HighCmd in, HighState back on UDP 192.168.123.220:8082" "$work/sim.log" ||
  { echo "WRONG: the MC did not serve the vendor address"; fail=1; }
echo "--- ground truth"
head -1 "$work/truth.log"
x=$(truth_value "$work/truth.log" final_x_m)
y=$(truth_value "$work/truth.log" final_y_m)
height=$(truth_value "$work/truth.log" final_height_m)
feet=$(truth_value "$work/truth.log" final_feet_down)
# the sim starts the trunk at the world origin: the sport frame starts within a few cm of it
if [[ -z "$x" ]] || ! awk -v x="$x" -v y="$y" -v h="$height" 'BEGIN {exit !(sqrt(x*x + y*y) < 0.2 && h > 0.18)}' ||
   [[ "$feet" != 1111 ]]; then
  echo "WRONG: final trunk at (${x}, ${y}) m, height ${height} m, feet down ${feet}: not back at (0, 0) standing"
  fail=1
else
  echo "seen: the robot walked the timeline and stands back at ($x, $y) m, height $height m, four feet down (sim_truth)"
fi
exit "$fail"
