#!/usr/bin/env bash
# One of the seed's Python examples through the stacked pair (issue 42), inside scripts/stack.sh:
# the high-level test that runs it unmodified against `cerebellum sim` runs it against MC B
# instead, judging every step in order in B's responses, while A's sim_truth is watched: the robot
# never falls (below), it stood (highest trunk above 0.22 m) and it lies at the end (below 0.15 m);
# in the basic-motion example it rose onto its hind feet (largest tilt above 60 deg).
# - sequential (tests/io/lcm_highlevel/seed_sequential.sh, section 2.4.2): stand, body height, a leg
#   up and down, step and rotate, get down;
# - basic_motion (tests/io/lcm_highlevel/seed_basic_motion.sh, section 2.4.1): stand, the hand shake
#   (a named motion, 62/2), the two-leg stand (64), head up and down (judged on A's truth), body
#   height, the turning trot, lie down.
#   stack_seed_example.sh sequential|basic_motion <cerebellum> <work dir> <seeds dir> <python3> <types dir>
set -u
root=$(cd "$(dirname "$0")/../.." && pwd)
example=$1
shift
case $example in
  sequential|basic_motion) ;;
  *) echo "stack_seed_example.sh: unknown example '$example' (sequential or basic_motion)" >&2; exit 2 ;;
esac
work=$2
python=$4
types=$5
# the sequential example never leaves four feet: any tilt over 35 deg is a fall; the basic-motion
# example stands on its hind feet (mode 64, the trunk near vertical but high): a fall there is a
# trunk tilted over 35 deg below 0.15 m, on its side or back
if [[ $example == sequential ]]; then fall_key=largest_tilt_deg; else fall_key=largest_low_tilt_deg; fi
# A's truth: where the example's own checks (the pose watch) and ours listen
export SIM_TRUTH_URL="udpm://239.255.76.67:7680?ttl=0"
mkdir -p "$work"
PYTHONPATH="$types" "$python" "$root/scripts/sim_truth_watch.py" --url "$SIM_TRUTH_URL" \
  --idle 30 > "$work/truth.log" 2>&1 &
watcher=$!
bash "$root/tests/io/lcm_highlevel/seed_$example.sh" "$@"
status=$?
sleep 1  # the get-down's last second on A's truth
kill -INT "$watcher"
wait "$watcher"
cat "$work/truth.log"
value() { sed -n "s/^$1=//p" "$work/truth.log"; }
check() {  # check <what> <awk condition on v>
  if awk -v v="$(value "$2")" "BEGIN { exit !($3) }"; then echo "stack_seed_example: $1: yes"; else
    echo "stack_seed_example: WRONG: $1 ($2=$(value "$2"))"; status=1; fi
}
check "never fell ($fall_key under 35 deg)" "$fall_key" "v != \"\" && v < 35"
check "stood (highest trunk above 0.22 m)" highest_height_m "v != \"\" && v > 0.22"
check "lies at the end (below 0.15 m)" final_height_m "v != \"\" && v < 0.15"
if [[ $example == basic_motion ]]; then
  check "rose onto its hind feet (largest tilt above 60 deg)" largest_tilt_deg "v != \"\" && v > 60"
fi
[[ $status -eq 0 ]] && echo "stack_seed_example: ok"
exit "$status"
