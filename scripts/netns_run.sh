#!/usr/bin/env bash
# Runs a command inside a private network namespace with only a multicast-capable loopback, so
# LCM traffic (UDP multicast) never reaches a real interface, and with a private /dev/shm, so the
# shared-memory objects of a simulation (served by default) never meet another test's. Needs root
# or user namespaces.
#   scripts/netns_run.sh <command> [args...]
set -euo pipefail
if [[ $# -eq 0 ]]; then
  echo "usage: $0 <command> [args...]" >&2
  exit 2
fi
if [[ "${CEREBELLUM_IN_NETNS:-}" == 1 ]]; then
  exec "$@"
fi
unshare_args=(--net --mount)
[[ $(id -u) -eq 0 ]] || unshare_args+=(--map-root-user)
exec unshare "${unshare_args[@]}" -- bash -c '
  set -e
  ip link set lo up
  ip link set lo multicast on
  ip route add 224.0.0.0/4 dev lo
  # the robot address of the AlienGo sport controller, so clients can target it unchanged
  ip addr add 192.168.123.220/32 dev lo
  mount -t tmpfs -o mode=1777 tmpfs /dev/shm
  export CEREBELLUM_IN_NETNS=1
  exec "$@"' netns_run "$@"
