#!/usr/bin/env bash
# The sweep's cost: its overhead per run against running the same cells alone (target: under
# 5 %), and its scaling from 1 to N local worker processes (docs/sweeps.md).
#   bench/sweep_overhead.sh [CEREBELLUM] [SCENARIO] [SLICE_COUNT] [N]
# Runs slice 0 of SLICE_COUNT of the scenario's grid (default: every 12th cell of
# bench/sweeps/push_sweep.yaml, 30 runs): once as a sweep with -j 1, once cell by cell alone
# (`cerebellum sweep FILE --cell K`, the replay command), then as a sweep with -j N (default: all
# cores). The overhead compares CPU seconds (user + system of every process), which a busy machine
# does not change much; the scaling compares wall seconds, which it does: say the load with them.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cerebellum=$(realpath "${1:-$root/build/src/cli/cerebellum}")
scenario=$(realpath "${2:-$root/bench/sweeps/push_sweep.yaml}")
slices=${3:-12}
jobs=${4:-$(nproc)}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
TIMEFORMAT='%R %U %S'

# "wall cpu" of a command, its children included
measure() {
  local line
  line=$({ time "$@" > /dev/null 2>&1; } 2>&1 | tail -1)
  awk '{printf "%.2f %.2f\n", $1, $2 + $3}' <<< "$line"
}

read -r sweep_wall sweep_cpu < <(measure "$cerebellum" sweep "$scenario" --out one --slice "0/$slices" -j 1)
cells=$(ls one/cells/*.csv | wc -l)
alone_cells() {
  local k
  for k in $(ls one/cells/*.csv | xargs -n1 basename | sed 's/\.csv$//' | sort -n); do
    "$cerebellum" sweep "$scenario" --cell "$k" > /dev/null 2>&1 || true
  done
}
read -r alone_wall alone_cpu < <(measure alone_cells)
read -r many_wall many_cpu < <(measure "$cerebellum" sweep "$scenario" --out many --slice "0/$slices" -j "$jobs")
cmp -s <(cat one/cells/*.csv | sort) <(cat many/cells/*.csv | sort) || { echo "the -j 1 and -j $jobs rows differ" >&2; exit 1; }

echo "| runs | alone: CPU s | sweep -j 1: CPU s | overhead | sweep -j 1: wall s | sweep -j $jobs: wall s | speed-up | load average |"
echo "|---|---|---|---|---|---|---|---|"
awk -v n="$cells" -v a="$alone_cpu" -v s="$sweep_cpu" -v w1="$sweep_wall" -v wn="$many_wall" -v load="$(cut -d' ' -f1-3 /proc/loadavg)" \
  'BEGIN { printf "| %d | %.1f | %.1f | %+.1f %% | %.1f | %.1f | %.2f | %s |\n", n, a, s, 100 * (s - a) / a, w1, wn, w1 / wn, load }'
