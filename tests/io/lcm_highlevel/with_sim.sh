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
source "$(dirname "$0")/../../seed_support.sh"
start_sim "$work/sim.log" "$cerebellum" sim --speed 1 --config "$work/highlevel.yaml"
sim=$sim_pid
"$@"
status=$?
kill -INT "$sim"
wait "$sim"
echo "--- MC log (joint lines left out)"
grep -v '^    ' "$work/sim.log"
exit "$status"
