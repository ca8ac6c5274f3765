#!/usr/bin/env bash
# Installs every Debian package cerebellum needs. Safe to run twice: skips what is present.
set -euo pipefail
packages=(
  build-essential cmake pkg-config git
  liblcm-dev liblcm-bin libglib2.0-dev liblcm-java default-jdk-headless
  libmujoco-dev libeigen3-dev libtomlplusplus-dev libyaml-cpp-dev
  libgtest-dev libgmock-dev libbenchmark-dev libalglib-dev
  coinor-libipopt-dev  # the flip planner (src/control/flip_plan, bench/plan_flip)
  iproute2 util-linux python3 python3-matplotlib python3-dev python3-setuptools python3-toml
  libsdl2-dev
  libglfw3-dev libegl-dev libegl-mesa0 libgl1-mesa-dri ffmpeg xvfb xauth xdotool
  clang libclang-rt-14-dev
  slurm-wlm munge  # cerebellum sweep --slurm and its single-node test (tests/cli/slurm_single_node.sh)
)
# installed for this machine's architecture (or for all): a foreign-architecture copy (an arm64
# -dev package of a cross build) does not count, and the native one is asked for by name
native=$(dpkg --print-architecture)
missing=()
for p in "${packages[@]}"; do
  { dpkg-query -W -f='${Status} ${Architecture}\n' "$p" "$p:$native" 2>/dev/null || true; } |
    grep -qE "^install ok installed ($native|all)$" || missing+=("$p:$native")
done
if ((${#missing[@]} == 0)); then
  echo "install_deps: all ${#packages[@]} packages present"
else
  echo "install_deps: installing ${missing[*]}"
  sudo_cmd=()
  [[ $(id -u) -eq 0 ]] || sudo_cmd=(sudo)
  "${sudo_cmd[@]}" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
# LCM's Python module, built from Debian's lcm source package (Debian ships no binary of it)
"$(dirname "$0")/install_lcm_python.sh"
