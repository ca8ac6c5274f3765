#!/usr/bin/env bash
# The stacked pair's real-time test run N times in a row, every second run beside four busy loops,
# to see how often the host's stalls trip it (docs/benchmarks/real-robot-log.md):
#   bash bench/stack_trials.sh [N] [BUILD_DIR]      (default 8, build)
# Prints each failure's reason and, at the end, passes, failures and B's link losses per run (the
# kill of A at the end of each run is one).
set -uo pipefail
runs=${1:-8}
root=$(cd "$(dirname "$0")/.." && pwd)
build=$(cd "${2:-$root/build}" && pwd)
pass=0
fail=0
losses=""
busy=()
stop_busy() { ((${#busy[@]})) && kill "${busy[@]}" 2>/dev/null; wait "${busy[@]}" 2>/dev/null; busy=(); }
trap stop_busy EXIT
for ((run = 1; run <= runs; run++)); do
  if ((run % 2 == 0)); then
    for _ in 1 2 3 4; do (while :; do :; done) & busy+=($!); done
  fi
  # one attempt per run: the test's second attempt would hide what is counted here
  if (cd "$build" && "$root/scripts/stack.sh" --cerebellum "$build/src/cli/cerebellum" \
        --logs "$build/bench/stack_trials" env "PYTHONPATH=$build/lcm/python" /usr/bin/python3 \
        "$root/tests/cli/stack_walk.py" "$build/src/cli/cerebellum" 0.8 > "$build/bench/stack_trials.out" 2>&1); then
    pass=$((pass + 1))
  else
    fail=$((fail + 1))
    echo "run $run: $(grep -h 'FAILED' "$build/bench/stack_trials.out" | head -1)"
  fi
  losses="$losses $(grep -c 'link lost' "$build/bench/stack_trials/b-run.log")"
  stop_busy
done
echo "stack_trials: $pass passed, $fail failed of $runs; B's link losses per run:$losses"
