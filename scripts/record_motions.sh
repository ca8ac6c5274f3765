#!/usr/bin/env bash
# A video of each named motion (mode 62) or jump (mode 16), or of the two-leg stand (64): for
# every id, the MC on the simulated robot records build/motions/motion_<id>.mp4
# (build/jumps/jump_<id>.mp4, the flips jump_20.mp4 and jump_21.mp4, build/two_legs/two_leg_0.mp4) while `cerebellum cmd`
# stands the robot up and runs it, inside a private network namespace; the jump down a stair (9)
# starts on a 10 cm landing (config/demo_stair.yaml). docs/motions.md and docs/jumps.md link the
# files.
#   scripts/record_motions.sh [--jumps | --two-leg] [ids...]
#     (default: every shipped motion, or every jump; SIZE=WxH, default 640x360)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
if [[ "${1:-}" != "--inside" ]]; then
  "$root/scripts/install_deps.sh"
  "$root/scripts/build.sh" cerebellum
  exec "$root/scripts/netns_run.sh" "$0" --inside "$@"
fi
shift
kind=motion
if [[ "${1:-}" == "--jumps" ]]; then
  kind=jump
  shift
elif [[ "${1:-}" == "--two-leg" ]]; then
  kind=two_leg
  shift
fi
cerebellum=$root/build/src/cli/cerebellum
out=$root/build/${kind}s
mkdir -p "$out"
ids=("$@")
if [[ ${#ids[@]} -eq 0 ]]; then
  case $kind in
    motion) ids=($(sed -n 's/^id = //p' "$root"/config/motions/*.toml)) ;;
    jump) ids=(0 1 2 3 4 5 6 9 20 21) ;;  # 20, 21: the back and the front flip
    two_leg) ids=(0) ;;
  esac
fi
# the bar of each video's rendering comes to this terminal (fd 3), not into the sim's log
exec 3>&1
progress=()
[[ -t 1 ]] && progress=(--progress-to /dev/fd/3)
count=0
for id in "${ids[@]}"; do
  count=$((count + 1))
  echo "[$count/${#ids[@]}] $kind $id: recording"
  config=$root/config/demo.yaml
  [[ $kind != jump || "$id" != 9 ]] || config=$root/config/demo_stair.yaml
  "$cerebellum" sim --config "$config" --speed 1 --record "$out/${kind}_$id.mp4" \
    --record-size "${SIZE:-640x360}" "${progress[@]}" > "$out/${kind}_$id.log" 2>&1 &
  sim=$!
  for _ in $(seq 100); do grep -q "cerebellum ready" "$out/${kind}_$id.log" && break; sleep 0.1; done
  "$cerebellum" cmd stand --hold 0.5 > /dev/null
  if [[ $kind == motion ]]; then
    if "$cerebellum" cmd raw --mode 62 --gait "$id" --timeout 60 --hold 1.5; then result=done; else result=FAILED; fi
  elif [[ $kind == two_leg ]]; then
    if "$cerebellum" cmd raw --mode 64 --gait "$id" --timeout 20 --hold 1.5; then result=done; else result=FAILED; fi
  else
    # a jump starts from a still stand
    "$cerebellum" cmd raw --mode 11 --gait 1 --timeout 10 --hold 1.0 > /dev/null
    if "$cerebellum" cmd raw --mode 16 --gait "$id" --timeout 10 --hold 1.5; then result=done; else result=FAILED; fi
  fi
  kill -INT "$sim"
  wait "$sim" || true
  echo "$kind $id: $result, video $out/${kind}_$id.mp4"
done
