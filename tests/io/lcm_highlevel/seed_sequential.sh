#!/usr/bin/env bash
# The seed's sequential-motion example (section 2.4.2 of shared/seeds/000_*.txt), taken from the
# seed at test time and run unmodified against the MC (with_sim.sh runs it) with a sequence file
# of ours (the seed names cyberdog2_ctrl.toml but does not give it), answering its file prompt
# with 0. It sends every step within a second and the MC's duration queue times them; the
# responses recorded by `cerebellum status` must show each step in order. The example then
# heartbeats for 60 s; the test interrupts it (Ctrl-C: it sends PureDamper) once the last step ran.
#   seed_sequential.sh <cerebellum> <work dir> <seeds dir> <python3> <generated python types dir>
set -u
cerebellum=$1
work=$2
seeds=$3
python=$4
types=$5
source "$(dirname "$0")/../../seed_support.sh"
seed=$(seed_file "$seeds") || exit $?
run="$work/run"
rm -rf "$run" && mkdir -p "$run"
example="$work/seed_sequential.py"
extract_code_block "$seed" '^#### 2\.4\.2' '^```python' "$example" "Input a toml ctrl file number"
cp "$(dirname "$0")/seed_sequential/cyberdog2_ctrl.toml" "$run/"
start_status_recorder "$cerebellum" "$work/status.log"
(cd "$run" && echo 0 | PYTHONPATH="$types" timeout -s INT 90 "$python" "$example") > "$work/example.log" 2>&1 &
client=$!
# the whole sequence lasts 16.5 s of robot time
for _ in $(seq 400); do
  grep -q '^mode 7 gait 1 bar 100' "$work/status.log" && break
  kill -0 "$client" 2>/dev/null || break
  sleep 0.1
done
kill -INT "$client" 2>/dev/null
wait "$client"
sleep 0.5
stop_status_recorder
cat "$work/example.log"
distinct_steps "$work/status.log" 11 "$work/steps.log"
grep -v 'switch 1 (TRANS' "$work/steps.log"
fail=0
steps_log="$work/steps.log"
from=1
expect "stand up (12)" '^mode 12 gait 0 bar 100 '
expect "body height (21/5)" '^mode 21 gait 5 '
expect "right hind leg up (21/2, contact 0xb)" '^mode 21 gait 2 bar [0-9]+ switch [01] .*contact 0xb'
expect "put down (21/0, all four feet)" '^mode 21 gait 0 bar [0-9]+ switch [01] .*contact 0xf'
expect "step and rotate (11/27)" '^mode 11 gait 27 '
expect "get down (7/1)" '^mode 7 gait 1 bar 100 '
if grep -q "switch 5" "$work/steps.log"; then echo "WRONG: a step was refused (BAN_TRANS)"; fail=1; fi
exit "$fail"
