#!/usr/bin/env bash
# Builds and runs every benchmark, each pinned to one core; results go to build/bench/results/:
# Google Benchmark JSON (<name>.json) and each benchmark's printed output (<name>.txt). Then
# bench/check_page.py compares the rows of docs/benchmarks.md that claim a verdict with them and
# fails the run if one is contradicted.
#   bench/run.sh [benchmark name filter]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/install_deps.sh"
"$root/scripts/build.sh"
out="$root/build/bench/results"
mkdir -p "$out"
filter=${1:-}
ran=()
chosen=()
for exe in "$root"/build/bench/*_bench; do
  name=$(basename "$exe")
  [[ -z "$filter" || "$name" == *"$filter"* ]] && chosen+=("$exe")
done
started=$SECONDS
for exe in "${chosen[@]}"; do
  name=$(basename "$exe")
  # progress: which of how many, and the time left at the pace so far (benchmarks differ a lot)
  done_count=${#ran[@]}
  left=""
  ((done_count > 0)) && left=", about $(((SECONDS - started) * (${#chosen[@]} - done_count) / done_count / 60)) min left"
  echo "== [$((done_count + 1))/${#chosen[@]}] $name ($(((SECONDS - started) / 60)) min so far$left)"
  ran+=("$name")
  taskset -c 1 "$exe" --benchmark_out="$out/$name.json" --benchmark_out_format=json | tee "$out/$name.txt" ||
    echo "== $name: some targets were missed (see its table)"
done
# the locomotion benchmark's velocity traces as a picture
if [[ -f "$out/locomotion_velocity.csv" ]]; then
  /usr/bin/python3 "$root/bench/plot_locomotion.py" "$out/locomotion_velocity.csv" "$root/docs/images/locomotion_velocity.png"
fi
# the page against what this run printed: a row its own benchmark contradicts fails the run
if ((${#ran[@]} == 0)); then
  echo "bench/run.sh: 0 rows checked, 0 contradicted (no benchmark matched '$filter')"
  exit 0
fi
/usr/bin/python3 "$root/bench/check_page.py" --page "$root/docs/benchmarks.md" --results "$out" --bench "${ran[@]}" \
  --label bench/run.sh
