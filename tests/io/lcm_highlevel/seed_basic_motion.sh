#!/usr/bin/env bash
# The seed's Python basic-motion example (section 2.4.1 of shared/seeds/000_*.txt), taken from the
# seed at test time and run unmodified against the MC (with_sim.sh runs it), while
# `cerebellum status` records the responses. Checks every step in order: stand (12), the hand
# shake (62/2) run to its end, the two-leg stand (64) run to its end, head up / down (21/0), body
# height (21/5), turning trot (11/26), lie down (7).
#   seed_basic_motion.sh <cerebellum> <work dir> <seeds dir> <python3> <generated python types dir>
set -u
cerebellum=$1
work=$2
seeds=$3
python=$4
types=$5
source "$(dirname "$0")/../../seed_support.sh"
seed=$(seed_file "$seeds") || exit $?
example="$work/seed_basic_motion.py"
extract_code_block "$seed" '^#### 2\.4\.1' '^```python' "$example" "robot_control_cmd"
start_status_recorder "$cerebellum" "$work/status.log"
# the trunk's pitch on the simulation's truth while the example poses the body
PYTHONPATH="$types" "$python" "$(dirname "$0")/pose_truth_watch.py" > "$work/pose_truth.log" 2>&1 &
pose_watch=$!
PYTHONPATH="$types" timeout 150 "$python" "$example"
result=$?
sleep 1  # the example stops once it sees its last mode; let the recorder print it too
stop_status_recorder
kill -INT "$pose_watch" 2>/dev/null
wait "$pose_watch" 2>/dev/null
echo "example exit status: $result"
[[ $result -eq 0 ]] || exit 1
# the distinct response lines, in order
distinct_steps "$work/status.log" 9 "$work/steps.log"
print_steps "$work/steps.log"
fail=0
steps_log="$work/steps.log"
from=1
# responses are sampled at 50 Hz: the example moves on at bar >= 95, the recorder may see 90-94 last
expect "stand up nearly done (12; the example waits for bar >= 95)" '^mode 12 gait 0 bar (9[0-9]|100) '
expect "hand shake running (62/2)" '^mode 62 gait 2 bar [1-9][0-9]? switch [15] '
# the motion's entry ends with the motion: the pose hold (21/3) follows bar 99
expect "hand shake nearly done (62/2, bar >= 95)" '^mode 62 gait 2 bar 9[5-9] '
# the example sends 64 once its own wait for 62/2 times out (10 s of wall time; the hand shake
# lasts 9 s of robot time), and moves on at bar >= 95
expect "two-leg stand running (64)" '^mode 64 gait 0 bar [0-9]+ switch 1 '
expect "two-leg stand nearly done (64, bar >= 90)" '^mode 64 gait 0 bar (9[0-9]|100) '
expect "head up / down (21/0)" '^mode 21 gait 0 bar [0-9]+ switch 0 '
expect "body height (21/5)" '^mode 21 gait 5 bar [0-9]+ switch 0 '
expect "turning trot (11/26)" '^mode 11 gait 26 bar [0-9]+ switch 0 '
expect "lie down (7)" '^mode 7 gait 0 bar [0-9]+ switch 0 '
# head up (+0.3: the nose rises), then head down (-0.3: incremental, so level again) on the truth;
# pitch is right-handed (negative: nose up)
cat "$work/pose_truth.log"
nose_up=$(sed -n 's/^most_nose_up_in_21_0_rad=//p' "$work/pose_truth.log")
level=$(sed -n 's/^pitch_when_21_5_came_rad=//p' "$work/pose_truth.log")
if ! awk -v p="$nose_up" 'BEGIN { exit !(p != "none" && p != "" && p < -0.25) }'; then
  echo "WRONG: head up did not raise the nose (most nose-up pitch in 21/0: $nose_up rad, want < -0.25)"; fail=1
fi
if ! awk -v p="$level" 'BEGIN { exit !(p != "none" && p != "" && p > -0.03 && p < 0.03) }'; then
  echo "WRONG: after head down the trunk is not level (pitch when 21/5 came: $level rad, want within 0.03)"; fail=1
fi
# the two-leg stand was neither refused nor ended by a protection
if grep -Eq '^mode 64 .* switch [2-7] ' "$work/steps.log"; then
  echo "WRONG: the two-leg stand refused or protected:"; grep -E '^mode 64 .* switch [2-7] ' "$work/steps.log" | head -3
  fail=1
fi
# the hand shake follows the stand directly
next_mode=$(awk '!/^mode 12 / && seen {print; exit} /^mode 12 / {seen = 1}' "$work/steps.log")
if [[ "$next_mode" != "mode 62 gait 2 "* ]]; then
  echo "WRONG: after the stand came '$next_mode', not the hand shake (62/2)"; fail=1
fi
exit "$fail"
