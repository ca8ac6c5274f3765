#!/usr/bin/env bash
# A video of each jump (mode 16): for every id, the MC on the simulated robot records
# build/jumps/jump_<id>.mp4 while `cerebellum cmd` stands the robot up and jumps, inside a private
# network namespace; the jump down a stair (9) starts on a 10 cm landing (config/demo_stair.yaml).
# docs/jumps.md links the files.
#   scripts/record_jumps.sh [ids...]      (default: 0 1 2 3 4 5 6 9; SIZE=WxH, default 640x360)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
if [[ "${1:-}" != "--inside" ]]; then
  "$root/scripts/install_deps.sh"
  "$root/scripts/build.sh" cerebellum
  exec "$root/scripts/netns_run.sh" "$0" --inside "$@"
fi
shift
cerebellum=$root/build/src/app/cerebellum
out=$root/build/jumps
mkdir -p "$out"
ids=("$@")
[[ ${#ids[@]} -gt 0 ]] || ids=(0 1 2 3 4 5 6 9)
for id in "${ids[@]}"; do
  config=$root/config/demo.yaml
  [[ "$id" != 9 ]] || config=$root/config/demo_stair.yaml
  "$cerebellum" sim --config "$config" --speed 1 --record "$out/jump_$id.mp4" \
    --record-size "${SIZE:-640x360}" > "$out/jump_$id.log" 2>&1 &
  sim=$!
  for _ in $(seq 100); do grep -q "cerebellum ready" "$out/jump_$id.log" && break; sleep 0.1; done
  "$cerebellum" cmd stand --hold 0.5 > /dev/null
  "$cerebellum" cmd raw --mode 11 --gait 1 --timeout 10 --hold 0.5 > /dev/null
  if "$cerebellum" cmd raw --mode 16 --gait "$id" --timeout 10 --hold 1.5; then result=done; else result=FAILED; fi
  kill -INT "$sim"
  wait "$sim" || true
  echo "jump $id: $result, video $out/jump_$id.mp4"
done
