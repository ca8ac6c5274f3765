#!/usr/bin/env bash
# Runs every libFuzzer program of tests/fuzz for SECONDS each (default 10) on a scratch copy of its
# seed corpus, in the sanitized build (scripts/build_sanitized.sh). Prints each target's runs
# and coverage; a crash, leak, sanitizer report or failed check stops it with the reproducer.
#   scripts/fuzz.sh [SECONDS] [target...]      (targets: high_cmd robot_control_cmd motor_ctrl
#                                               user_gait_file motion_file shm_command sim_command_text
#                                               config_yaml fault_scenario)
# FUZZ_SEED=N fixes libFuzzer's random seed (CI uses 1, so a run can be repeated); default: random.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
seconds=${1:-10}
shift || true
targets=("$@")
[[ ${#targets[@]} -gt 0 ]] ||
  targets=(high_cmd robot_control_cmd motor_ctrl user_gait_file motion_file shm_command sim_command_text config_yaml
    fault_scenario)
programs=()
for t in "${targets[@]}"; do programs+=("fuzz_$t"); done
"$root/scripts/build_sanitized.sh" "${programs[@]}" > "$root/build-sanitize/fuzz-build.log" 2>&1 ||
  { tail -30 "$root/build-sanitize/fuzz-build.log"; exit 1; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
for t in "${targets[@]}"; do
  mkdir -p "$work/$t"
  cp "$root/tests/fuzz/corpus/$t/"* "$work/$t/"
  log="$root/build-sanitize/fuzz_$t.log"
  if ! (cd "$work" && "$root/build-sanitize/tests/fuzz/fuzz_$t" -max_total_time="$seconds" -seed="${FUZZ_SEED:-0}" -max_len=65536 \
        -timeout=5 -rss_limit_mb=2048 -print_final_stats=1 "$work/$t" > "$log" 2>&1); then
    echo "fuzz $t: FAILED (reproducer in $work, kept: $log)"
    tail -40 "$log"
    trap - EXIT
    exit 1
  fi
  runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log")
  cov=$(grep -o 'cov: [0-9]*' "$log" | tail -1)
  echo "fuzz $t: $runs inputs in ${seconds} s, $cov, no failure"
done
