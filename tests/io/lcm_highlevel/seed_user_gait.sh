#!/usr/bin/env bash
# The seed's customized-gait example (section 2.4.3 of shared/seeds/000_*.txt), taken from the
# seed at test time and run unmodified against the MC (with_sim.sh runs it) with our moonwalk
# (config/user_gaits, human-form parameters that the example converts itself) and a sequence file
# of ours, while `cerebellum status` records the responses: both files stored, the gait run as
# motion 62/110 to its end, then the lie-down.
#   seed_user_gait.sh <cerebellum> <work dir> <seeds dir> <python3> <generated python types dir> <source dir>
set -u
cerebellum=$1
work=$2
seeds=$3
python=$4
types=$5
source_dir=$6
source "$(dirname "$0")/../../seed_support.sh"
seed=$(seed_file "$seeds") || exit $?
run="$work/run"
rm -rf "$run" && mkdir -p "$run"
example="$work/seed_user_gait.py"
extract_code_block "$seed" '^#### 2\.4\.3' '^```python' "$example" "Gait_Params_moonwalk.toml"
cp "$source_dir/config/user_gaits/moonwalk_def.toml" "$run/Gait_Def_moonwalk.toml"
cp "$source_dir/config/user_gaits/moonwalk_params.toml" "$run/Gait_Params_moonwalk.toml"
cp "$(dirname "$0")/seed_user_gait/Usergait_List.toml" "$run/Usergait_List.toml"
start_status_recorder "$cerebellum" "$work/status.log"
(cd "$run" && PYTHONPATH="$types" timeout 60 "$python" "$example")
result=$?
sleep 1
stop_status_recorder
echo "example exit status: $result"
[[ $result -eq 0 ]] || exit 1
distinct_steps "$work/status.log" 9 "$work/steps.log"
grep -v 'switch 1 (TRANS' "$work/steps.log"
fail=0
steps_log="$work/steps.log"
from=1
expect "the uploaded gait runs as a motion (62/110)" '^mode 62 gait 110 bar [1-9][0-9]? switch 1 '
expect "it nearly ends (62/110, bar >= 95)" '^mode 62 gait 110 bar 9[5-9] '
expect "then the lie-down (7/1)" '^mode 7 gait 1 '
# the example's 75 timed "heartbeats" (new life_counts repeating the last step) all fit the queue
if grep -Eq "beyond the .*queue|queue is full" "$work/sim.log"; then
  echo "WRONG: the MC dropped commands of the example beyond its queue:"
  grep -E "beyond the .*queue|queue is full" "$work/sim.log" | head -3
  fail=1
else
  echo "seen: no command dropped beyond the queue"
fi
exit "$fail"
