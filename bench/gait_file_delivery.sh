#!/usr/bin/env bash
# How often a user_gait_file of a given size reaches the MC and is answered: LCM sends a large
# message as UDP fragments, and one lost fragment loses the file (the client hears nothing).
# Uploads converted moonwalk parameters padded to each size, 20 times, against `cerebellum sim`
# in a private network namespace, and prints answered / sent per size (docs/benchmarks.md).
#   bench/gait_file_delivery.sh [sizes in KiB...]      (default: 8 32 64 128 200 250)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
if [[ "${1:-}" != "--inside" ]]; then
  "$root/scripts/build.sh" cerebellum > /dev/null
  exec "$root/scripts/netns_run.sh" "$0" --inside "$@"
fi
shift
cerebellum=$root/build/src/cli/cerebellum
work=$(mktemp -d)
trap 'kill -INT $sim 2>/dev/null || true; rm -rf "$work"' EXIT
sizes=("$@")
[[ ${#sizes[@]} -gt 0 ]] || sizes=(8 32 64 128 200 250)
"$cerebellum" sim --speed 1 > "$work/sim.log" 2>&1 &
sim=$!
for _ in $(seq 100); do grep -q "cerebellum ready" "$work/sim.log" && break; sleep 0.1; done
"$cerebellum" gait convert "$root/config/user_gaits/moonwalk_params.toml" > "$work/converted.toml"
echo "| file size | answered / sent |"
echo "|---|---|"
for kib in "${sizes[@]}"; do
  # the converted steps repeated (and a comment) up to the size: a valid TOML text of that length
  file="$work/params_$kib.toml"
  cp "$work/converted.toml" "$file"
  while (( $(stat -c %s "$file") < kib * 1024 - 400 )); do tail -n +2 "$work/converted.toml" >> "$file"; done
  head -c $((kib * 1024)) "$file" > "$file.cut" && mv "$file.cut" "$file"
  answered=0
  for _ in $(seq 20); do
    "$cerebellum" gait upload "$root/config/user_gaits/moonwalk_def.toml" "$file" --ttl 0 --timeout 1 \
      | grep -q "$(basename "$file"): no answer" || answered=$((answered + 1))
  done
  echo "| $(stat -c %s "$file") bytes | $answered / 20 |"
done
