#!/usr/bin/env bash
# Power-on as on the robot: a plain `cerebellum sim` (no configuration) lies with the motors off,
# and whichever client comes first takes the robot; the second is refused as the robot refuses it,
# and the MC's log says why. Two runs, each on a fresh plain simulation:
#   1. the seed's motor SDK example (section 3.4) first: it stands the robot (sim_truth), then a
#      high-level stand (mode 12) is refused (BAN_TRANS, "a low-level client holds the robot");
#   2. a high-level stand first (mode 12): the robot stands, then the seed's example is refused
#      (the MC logs "motor_ctrl refused", the motors stay with the high-level MC).
# Run inside scripts/netns_run.sh.
#   seed_power_on_order.sh <cerebellum> <work dir> <seeds dir> <c++ compiler>
#                          <include dirs, ':'-separated> <libcyber_dog_motor_sdk.so>
#                          <generated python types dir>
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
fail=0

# stands_at_end <truth log> <what stood it>: the trunk is at least 0.2 m high at the end (sim_truth)
stands_at_end() {
  local height
  height=$(truth_value "$1" final_height_m)
  if [[ -z "$height" ]] || ! awk -v h="$height" 'BEGIN {exit !(h >= 0.2)}'; then
    echo "WRONG: the robot is not standing at the end (final height '$height' m)"; fail=1
  else
    echo "seen: $2 stood the robot ($height m, sim_truth)"
  fi
}

echo "=== 1. the motor SDK example first, on a plain cerebellum sim"
start_truth_watch "$work/truth1.log" "$python_types"
start_sim "$work/sim1.log" "$cerebellum" sim --speed 1 --duration 12
sim=$sim_pid
"$work/seed_example_motor_ctrl" > "$work/example1.log" 2>&1 &
example=$!
sleep 4  # the example has activated (2 s) and is laying the legs out
"$cerebellum" cmd stand --timeout 3 --hold 0 > "$work/cmd1.log" 2>&1
cmd_status=$?
wait "$sim"
kill -INT "$example" 2>/dev/null
wait "$example"
wait "$truth_pid"
grep -v '^    ' "$work/sim1.log" | grep -E "startup|motor sdk|refused" | head -8
cat "$work/cmd1.log"
[[ $cmd_status -ne 0 ]] || { echo "WRONG: the high-level stand was taken while the motor SDK held the robot"; fail=1; }
grep -q "refused mode 12 .*a low-level client holds the robot" "$work/sim1.log" ||
  { echo "WRONG: the MC's log does not say why the stand was refused"; fail=1; }
grep -q "^motor sdk: motor mode yes" "$work/sim1.log" || { echo "WRONG: the motor SDK never held the robot"; fail=1; }
stands_at_end "$work/truth1.log" "the seed's example (the high-level stand was refused)"

echo "=== 2. a high-level stand first, on a plain cerebellum sim"
start_truth_watch "$work/truth2.log" "$python_types"
start_sim "$work/sim2.log" "$cerebellum" sim --speed 1 --duration 12
sim=$sim_pid
# the stand keeps its heartbeat until stopped: a silent client would be laid down (PureDamper),
# from where the motor SDK may take over, as on the robot
"$cerebellum" cmd stand --timeout 8 > "$work/cmd2.log" 2>&1 &
stand=$!
sleep 4  # the stand is done (the recovery stand takes about 2.5 s)
"$work/seed_example_motor_ctrl" > "$work/example2.log" 2>&1 &
example=$!
wait "$sim"
kill -INT "$example" "$stand" 2>/dev/null
wait "$example"
wait "$stand"
wait "$truth_pid"
grep -v '^    ' "$work/sim2.log" | grep -E "motor sdk|refused" | head -8
grep -q "motor_ctrl refused: .* has the robot" "$work/sim2.log" ||
  { echo "WRONG: the MC's log does not say why the motor SDK was refused"; fail=1; }
if grep -q "^motor sdk: motor mode yes" "$work/sim2.log"; then
  echo "WRONG: the motor SDK took the robot from the standing high-level MC"; fail=1
fi
stands_at_end "$work/truth2.log" "the high-level MC (the motor SDK was refused)"
exit "$fail"
