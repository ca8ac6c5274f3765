#!/usr/bin/env bash
# Runs a client command against `cerebellum sim --speed 1` (Off at start, high-level interface on)
# and prints the MC's log after it. Run it inside scripts/netns_run.sh.
#   with_sim.sh <cerebellum> <work dir> <client command...>
set -u
cerebellum=$1
work=$2
shift 2
mkdir -p "$work"
printf 'mc:\n  startup: off\nhighlevel:\n  enabled: true\n' > "$work/highlevel.yaml"
"$cerebellum" sim --speed 1 --config "$work/highlevel.yaml" > "$work/sim.log" 2>&1 &
sim=$!
for _ in $(seq 300); do
  grep -q "cerebellum ready" "$work/sim.log" && break
  kill -0 "$sim" 2>/dev/null || break
  sleep 0.1
done
if ! grep -q "cerebellum ready" "$work/sim.log"; then
  echo "with_sim: the MC did not start:"; cat "$work/sim.log"
  kill "$sim" 2>/dev/null
  exit 1
fi
"$@"
status=$?
kill -INT "$sim"
wait "$sim"
echo "--- MC log (joint lines left out)"
grep -v '^    ' "$work/sim.log"
exit "$status"
