#!/usr/bin/env bash
# The seed's sequential-motion example (section 2.4.2 of shared/seeds/000_*.txt) through the
# stacked pair (issue 42), inside scripts/stack.sh: the high-level test that runs it unmodified
# against `cerebellum sim` (tests/io/lcm_highlevel/seed_sequential.sh: stand, body height, a leg
# up and down, step and rotate, get down, each in order in the MC's responses) runs it against MC
# B instead, while A's sim_truth is watched: the robot never tips over (largest tilt under 35 deg),
# it stood (highest trunk above 0.22 m) and it lies at the end (below 0.15 m).
#   stack_seed_sequential.sh <cerebellum> <work dir> <seeds dir> <python3> <generated python types dir>
set -u
root=$(cd "$(dirname "$0")/../.." && pwd)
work=$2
python=$4
types=$5
mkdir -p "$work"
PYTHONPATH="$types" "$python" "$root/scripts/sim_truth_watch.py" --url "udpm://239.255.76.67:7680?ttl=0" \
  --idle 30 > "$work/truth.log" 2>&1 &
watcher=$!
bash "$root/tests/io/lcm_highlevel/seed_sequential.sh" "$@"
status=$?
sleep 1  # the get-down's last second on A's truth
kill -INT "$watcher"
wait "$watcher"
cat "$work/truth.log"
value() { sed -n "s/^$1=//p" "$work/truth.log"; }
check() {  # check <what> <awk condition on v>
  if awk -v v="$(value "$2")" "BEGIN { exit !($3) }"; then echo "stack_seed_sequential: $1: yes"; else
    echo "stack_seed_sequential: WRONG: $1 ($2=$(value "$2"))"; status=1; fi
}
check "never tipped over (largest tilt under 35 deg)" largest_tilt_deg "v != \"\" && v < 35"
check "stood (highest trunk above 0.22 m)" highest_height_m "v != \"\" && v > 0.22"
check "lies at the end (below 0.15 m)" final_height_m "v != \"\" && v < 0.15"
[[ $status -eq 0 ]] && echo "stack_seed_sequential: ok"
exit "$status"
