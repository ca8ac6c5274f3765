#!/usr/bin/env bash
# Runs a real-time test up to N times until it passes, saying each failed attempt: for tests of the
# stacked pair in real time, whose 20 ms link watch a virtual machine's host can trip by stopping a
# vCPU (docs/real-robot.md, docs/benchmarks/real-robot-log.md). A fault of ours fails every attempt.
#   real_time_attempts.sh N COMMAND [ARGS...]
set -uo pipefail
attempts=$1
shift
for ((attempt = 1; attempt <= attempts; attempt++)); do
  "$@" && exit 0
  status=$?
  echo "real_time_attempts: attempt $attempt of $attempts failed (exit $status)"
done
exit "$status"
