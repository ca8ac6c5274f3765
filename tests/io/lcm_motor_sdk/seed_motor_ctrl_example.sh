#!/usr/bin/env bash
# The seed's motor SDK example (section 3.4 of shared/seeds/000_*.txt), taken from the seed at test
# time, compiled unmodified against our custom_interface.hpp and libcyber_dog_motor_sdk the way a
# user's build would, and run against a plain `cerebellum sim --speed 1` (no configuration: the
# robot lies with the motors off, as after power-on, and the motor SDK is on).
# The example activates (2 s), lays the legs out (3 s), stands up (3 s) and holds until Ctrl-C;
# the simulation's ground truth (channel sim_truth) shows that it stood. Run inside
# scripts/netns_run.sh.
#   seed_motor_ctrl_example.sh <cerebellum> <work dir> <seeds dir> <c++ compiler>
#                              <include dirs, ':'-separated> <libcyber_dog_motor_sdk.so>
#                              <generated python types dir>
set -u
cerebellum=$1
work=$2
seeds=$3
cxx=$4
include_dirs=$5
sdk_library=$6
python_types=$7
source "$(dirname "$0")/../../seed_support.sh"
seed=$(seed_file "$seeds") || exit $?
rm -rf "$work" && mkdir -p "$work"
build_seed_motor_example "$seed" "$work" "$cxx" "$include_dirs" "$sdk_library"

# 12 s of robot time at real-time speed: start-up, activation 2 s, 3 s to lying, 3 s up, holding
start_truth_watch "$work/truth.log" "$python_types"
start_sim "$work/sim.log" "$cerebellum" sim --speed 1 --duration 12
sim=$sim_pid
"$work/seed_example_motor_ctrl" > "$work/example.log" 2>&1 &
example=$!
wait "$sim"
sim_status=$?
# the example runs until Ctrl-C: its own handler calls Stop() and main returns 0
kill -INT "$example" 2>/dev/null
wait "$example"
example_status=$?
wait "$truth_pid"  # ends once the simulation's truth has gone quiet
echo "--- example output (first lines)"
head -12 "$work/example.log"
echo "--- MC log (joint lines left out)"
grep -v '^    ' "$work/sim.log"
fail=0
[[ $sim_status -eq 0 ]] || { echo "WRONG: cerebellum sim exited with $sim_status"; fail=1; }
[[ $example_status -eq 0 ]] || { echo "WRONG: the example exited with $example_status after SIGINT"; fail=1; }
grep -q "^err_flag " "$work/example.log" || { echo "WRONG: the example never printed its data"; fail=1; }
# bit 1 (lost, > 500 ms) must be clear at the end: the example's commands are executed. Bit 0 is
# the late-frame warning (> 10 ms since the last frame): the example and the MC are two real-time
# processes, and on a loaded machine one late wake-up of the example near the end sets it, so it is
# not judged here (the lost bit and the communication-loss count are).
final_flag=$(sed -n 's/^motor sdk: motor mode yes, err_flag 0x\([0-9a-f]*\);.*/\1/p' "$work/sim.log" | tail -1)
if [[ -z "$final_flag" ]] || (( (16#$final_flag & 0x02) != 0 )); then
  echo "WRONG: the MC did not end in motor mode with err_flag bit 1 clear (found '${final_flag}')"; fail=1
fi
if ! grep -q " 0 communication losses;" "$work/sim.log"; then
  echo "WRONG: the MC saw the example's commands lost"; fail=1
fi
echo "--- ground truth"
head -1 "$work/truth.log"
height=$(truth_value "$work/truth.log" final_height_m)
tilt=$(truth_value "$work/truth.log" final_tilt_deg)
feet=$(truth_value "$work/truth.log" final_feet_down)
lowest=$(truth_value "$work/truth.log" lowest_height_m)
if [[ -z "$height" ]] || ! awk -v h="$height" -v t="$tilt" 'BEGIN {exit !(h >= 0.2 && t < 10)}' ||
   [[ "$feet" != 1111 ]]; then
  echo "WRONG: final trunk height '${height}' m, tilt '${tilt}' deg, feet down '${feet}': the robot did not stand"
  fail=1
else
  echo "seen: the robot stands, trunk height $height m, tilt $tilt deg, four feet down (lowest $lowest m; sim_truth)"
fi
exit "$fail"
