#!/usr/bin/env bash
# Checks that a program runs on the robot's board (aarch64, glibc 2.31) whatever its libraries:
# `file` says it is an aarch64 executable, statically linked; readelf finds no program interpreter,
# no dynamic section (so no NEEDED library) and no versioned symbol at all (so none newer than
# GLIBC_2.31). Exits 1 naming what failed. Usage: scripts/check_static_binary.sh <program>
# (scripts/build_robot.sh runs it on build-aarch64/src/cli/cerebellum; docs/robot-build.md)
set -uo pipefail
if [[ $# -ne 1 || ! -f "$1" ]]; then
  echo "usage: $0 <program>" >&2
  exit 2
fi
binary=$1
oldest_glibc=2.31  # the board's Ubuntu 20.04
failures=()
description=$(file -b "$binary")
echo "check: file: $description"
[[ "$description" == *"ARM aarch64"* ]] || failures+=("not an aarch64 program")
[[ "$description" == *"statically linked"* ]] || failures+=("not statically linked (file)")
headers=$(readelf -lW "$binary")
if grep -q "INTERP" <<<"$headers"; then
  failures+=("it asks for a program interpreter: $(grep -o 'Requesting program interpreter: [^]]*' <<<"$headers")")
fi
dynamic=$(readelf -dW "$binary")
if ! grep -q "There is no dynamic section" <<<"$dynamic"; then
  needed=$(grep NEEDED <<<"$dynamic" | grep -o '\[.*\]' | tr '\n' ' ')
  failures+=("it has a dynamic section (NEEDED: ${needed:-none})")
fi
# versioned symbols: a static program has none; a dynamic one names its glibc, e.g. GLIBC_2.34
versions=$( (readelf -VW "$binary"; readelf --dyn-syms -W "$binary") | grep -o 'GLIBC_[0-9][0-9.]*' | sort -uV)
newer=$(for v in $versions; do
  n=${v#GLIBC_}
  [[ $(printf '%s\n%s\n' "$oldest_glibc" "$n" | sort -V | tail -1) != "$oldest_glibc" ]] && echo "$v"
done | tr '\n' ' ')
echo "check: readelf: interpreter $(grep -c INTERP <<<"$headers"), dynamic section $(grep -qc 'There is no dynamic section' <<<"$dynamic" && echo none || echo present), glibc symbol versions: $(echo ${versions:-none})"
[[ -z "$newer" ]] || failures+=("it needs symbols newer than GLIBC_$oldest_glibc: $newer")
if ((${#failures[@]} > 0)); then
  for f in "${failures[@]}"; do echo "check: FAILED: $binary: $f" >&2; done
  exit 1
fi
echo "check: ok: $binary is a static aarch64 program, with no dynamic dependency and no glibc symbol version (runs on glibc $oldest_glibc)"
