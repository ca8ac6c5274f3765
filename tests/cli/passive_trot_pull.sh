#!/usr/bin/env bash
# Runs passive_trot_pull.py against `cerebellum sim --speed 1` (real time), inside a private
# network namespace (scripts/netns_run.sh).
#   passive_trot_pull.sh <cerebellum> <generated python types> <work dir> WAIT PULL
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/../seed_support.sh"
exe=$1
types=$2
work=$3
mkdir -p "$work"
cd "$work"
start_sim sim.log "$exe" sim --speed 1 --duration 60
trap 'kill -9 $sim_pid 2>/dev/null || true' EXIT
PYTHONPATH="$types" /usr/bin/python3 "$(dirname "${BASH_SOURCE[0]}")/passive_trot_pull.py" "$exe" "$4" "$5"
