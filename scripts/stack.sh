#!/usr/bin/env bash
# The stacked pair on one host (docs/real-robot.md): MC A is `cerebellum sim` serving the motor SDK
# and the lowlevel.h shared memory (config/stack/sim.yaml) in place of the robot's own MC, MC B is
# `cerebellum run` driving A through one of them and serving the high-level interfaces
# (config/stack/ROBOT.yaml: cyberdog2-motor-sdk, the default, or zsibot-shm). Both run paced by the
# wall clock in one private network namespace (scripts/netns_run.sh): nothing reaches a real
# interface.
#   scripts/stack.sh [--robot ROBOT] [--cerebellum EXE] [--b-cerebellum EXE [--b-emulator PROGRAM]]
#                    [--logs DIR] [COMMAND [ARGS...]]
# --b-cerebellum: B's own program (default: A's), e.g. the robot's aarch64 build run under
# --b-emulator qemu-aarch64-static (docs/robot-build.md)
# With a command: runs it in the namespace once both are ready, with STACK_A_PID, STACK_B_PID,
# STACK_A_LOG, STACK_B_LOG and STACK_ROBOT in its environment, then stops both and exits with its status.
# Without one: runs until Ctrl-C. e.g. scripts/stack.sh bash  (then: cerebellum cmd stand --ttl 0)
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
root=$(dirname "$here")
if [[ "${CEREBELLUM_IN_NETNS:-}" != 1 ]]; then
  exec "$here/netns_run.sh" "$0" "$@"
fi

exe=""
b_exe=""
b_emulator=()
logs=""
robot=cyberdog2-motor-sdk
while [[ $# -gt 0 ]]; do
  case $1 in
    --robot) robot=$2; shift 2 ;;
    --cerebellum) exe=$2; shift 2 ;;
    --b-cerebellum) b_exe=$2; shift 2 ;;
    --b-emulator) b_emulator=("$2"); shift 2 ;;
    --logs) logs=$2; shift 2 ;;
    --help|-h) sed -n '2,15p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) break ;;
  esac
done
if [[ -z "$exe" ]]; then
  for candidate in "$root/build/src/cli/cerebellum" "$(command -v cerebellum || true)"; do
    [[ -n "$candidate" && -x "$candidate" ]] && { exe=$candidate; break; }
  done
fi
[[ -x "$exe" ]] || { echo "stack.sh: no cerebellum program (give --cerebellum EXE)" >&2; exit 2; }
b_config="$root/config/stack/$robot.yaml"
if [[ "$robot" == sim || ! -f "$b_config" ]]; then
  echo "stack.sh: --robot $robot: no config/stack/$robot.yaml for MC B (cyberdog2-motor-sdk or zsibot-shm)" >&2
  exit 2
fi
b_exe=${b_exe:-$exe}
[[ -x "$b_exe" ]] || { echo "stack.sh: no program $b_exe for B (--b-cerebellum)" >&2; exit 2; }
logs=${logs:-$(mktemp -d /tmp/cerebellum-stack.XXXXXX)}
mkdir -p "$logs"
a_log="$logs/a-sim.log"
b_log="$logs/b-run.log"

# wait_ready <pid> <log> <name> <seconds>: the MC's ready line, or its log and exit 1
wait_ready() {
  local deadline=$((SECONDS + $4))
  while ((SECONDS < deadline)); do
    grep -q "cerebellum ready" "$2" && return 0
    kill -0 "$1" 2>/dev/null || break
    sleep 0.1
  done
  echo "stack.sh: $3 did not start:" >&2
  cat "$2" >&2
  return 1
}

# each MC's real-time settings (priority, CPUs, locked memory) are in its configuration's
# `realtime:` section, and each says at start what it got and what the system refused
a_pid=""
b_pid=""
stop_both() {
  # B first, so A sees its client go (the robot's own protection lies it down)
  [[ -n "$b_pid" ]] && kill -INT "$b_pid" 2>/dev/null && wait "$b_pid" 2>/dev/null
  [[ -n "$a_pid" ]] && kill -INT "$a_pid" 2>/dev/null && wait "$a_pid" 2>/dev/null
  return 0
}
trap stop_both EXIT
trap 'exit 130' INT TERM

"$exe" sim --speed 1 --config "$root/config/stack/sim.yaml" > "$a_log" 2>&1 &
a_pid=$!
wait_ready "$a_pid" "$a_log" "MC A (cerebellum sim)" 60
# B activates the robot before its ready line (a CyberDog2's motor mode: the robot lies 2 s first)
"${b_emulator[@]}" "$b_exe" run --config "$b_config" > "$b_log" 2>&1 &
b_pid=$!
wait_ready "$b_pid" "$b_log" "MC B (cerebellum run)" 60
echo "stack.sh: A (pid $a_pid, log $a_log) and B ($robot, pid $b_pid, log $b_log) ready"

export STACK_A_PID=$a_pid STACK_B_PID=$b_pid STACK_A_LOG=$a_log STACK_B_LOG=$b_log STACK_ROBOT=$robot
# note_logs: each MC's log without its healthy once-a-second state lines, for a failed run's reader
note_logs() {
  for side in "A:$a_log" "B:$b_log"; do
    echo "stack.sh: ${side%%:*}'s log (${side#*:}), all but the healthy state lines, last 40:"
    awk '/^    (FR|FL|RR|RL) q=/ { next } /^t= / && /guard=0x00/ && !/PROTECTED/ { next } { print "  | " $0 }' \
      "${side#*:}" | tail -40
  done
}
if [[ $# -gt 0 ]]; then
  status=0
  "$@" || status=$?
  if [[ $status -ne 0 ]]; then
    stop_both  # their closing counters first
    a_pid="" b_pid=""
    note_logs
  fi
  exit "$status"
fi
wait "$b_pid"
