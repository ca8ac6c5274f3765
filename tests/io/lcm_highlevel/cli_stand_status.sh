#!/usr/bin/env bash
# `cerebellum cmd stand` holds the robot up while `cerebellum status --count 3` reads it back once
# the stand-up has finished.
#   cli_stand_status.sh <cerebellum> <work dir>   (with_sim.sh runs the MC)
set -u
cerebellum=$1
work=$2
done_line='^mode 12 gait 0 bar 100 switch 0 (Done)'
"$cerebellum" cmd stand --hold 60 > "$work/cmd.log" 2>&1 &
cmd=$!
for _ in $(seq 300); do
  grep -q "reached" "$work/cmd.log" && break
  kill -0 "$cmd" 2>/dev/null || break
  sleep 0.1
done
cat "$work/cmd.log"
if ! grep -q "cmd stand: mode 12 gait 0 reached" "$work/cmd.log"; then
  kill "$cmd" 2>/dev/null
  exit 1
fi
# the client counts >= 95 % as reached; the last few percent follow
for _ in $(seq 20); do
  "$cerebellum" status --count 1 | grep -q "$done_line" && break
done
"$cerebellum" status --count 3 | tee "$work/status.log"
status=$?
kill -INT "$cmd"
wait "$cmd"
[[ $status -eq 0 ]] || exit 1
lines=$(grep -c "$done_line" "$work/status.log")
echo "status lines showing mode 12 with bar 100: $lines"
[[ $lines -eq 3 ]]
