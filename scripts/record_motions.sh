#!/usr/bin/env bash
# A video of each named motion (mode 62): for every id, the MC on the simulated robot records
# build/motions/motion_<id>.mp4 while `cerebellum cmd` stands the robot up and runs the motion,
# inside a private network namespace. docs/motions.md links the files.
#   scripts/record_motions.sh [ids...]      (default: every shipped motion; SIZE=WxH, default 640x360)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
if [[ "${1:-}" != "--inside" ]]; then
  "$root/scripts/install_deps.sh"
  "$root/scripts/build.sh" cerebellum
  exec "$root/scripts/netns_run.sh" "$0" --inside "$@"
fi
shift
cerebellum=$root/build/src/app/cerebellum
out=$root/build/motions
mkdir -p "$out"
ids=("$@")
[[ ${#ids[@]} -gt 0 ]] || ids=($(sed -n 's/^id = //p' "$root"/config/motions/*.toml))
for id in "${ids[@]}"; do
  "$cerebellum" sim --config "$root/config/demo.yaml" --speed 1 --record "$out/motion_$id.mp4" \
    --record-size "${SIZE:-640x360}" > "$out/motion_$id.log" 2>&1 &
  sim=$!
  for _ in $(seq 100); do grep -q "cerebellum ready" "$out/motion_$id.log" && break; sleep 0.1; done
  "$cerebellum" cmd stand --hold 0.5 > /dev/null
  if "$cerebellum" cmd raw --mode 62 --gait "$id" --timeout 60 --hold 1.5; then result=done; else result=FAILED; fi
  kill -INT "$sim"
  wait "$sim" || true
  echo "motion $id: $result, video $out/motion_$id.mp4"
done
