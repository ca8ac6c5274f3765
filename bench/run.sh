#!/usr/bin/env bash
# Builds and runs every benchmark, each pinned to one core; results go to build/bench/results/.
#   bench/run.sh [benchmark name filter]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/install_deps.sh"
"$root/scripts/build.sh"
out="$root/build/bench/results"
mkdir -p "$out"
filter=${1:-}
for exe in "$root"/build/bench/*_bench; do
  name=$(basename "$exe")
  [[ -z "$filter" || "$name" == *"$filter"* ]] || continue
  echo "== $name"
  taskset -c 1 "$exe" --benchmark_out="$out/$name.json" --benchmark_out_format=json || echo "== $name: some targets were missed (see its table)"
done
# the locomotion benchmark's velocity traces as a picture
if [[ -f "$out/locomotion_velocity.csv" ]]; then
  /usr/bin/python3 "$root/bench/plot_locomotion.py" "$out/locomotion_velocity.csv" "$root/docs/images/locomotion_velocity.png"
fi
