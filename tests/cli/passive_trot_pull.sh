#!/usr/bin/env bash
# Runs passive_trot_pull.py against `cerebellum sim --speed 1` (real time), inside a private
# network namespace (scripts/netns_run.sh).
#   passive_trot_pull.sh <cerebellum> <generated python types> <work dir> WAIT PULL
set -euo pipefail
exe=$1
types=$2
work=$3
mkdir -p "$work"
cd "$work"
"$exe" sim --speed 1 --duration 60 > sim.log 2>&1 &
sim=$!
trap 'kill -9 $sim 2>/dev/null || true' EXIT
for _ in $(seq 300); do grep -q "cerebellum ready" sim.log && break; sleep 0.1; done
grep -q "cerebellum ready" sim.log || { cat sim.log; echo "passive_trot_pull: the MC did not start"; exit 1; }
PYTHONPATH="$types" /usr/bin/python3 "$(dirname "${BASH_SOURCE[0]}")/passive_trot_pull.py" "$exe" "$4" "$5"
