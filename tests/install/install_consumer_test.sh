#!/usr/bin/env bash
# Installs the build tree into a temporary prefix and builds a consumer project against it.
#   install_consumer_test.sh <build dir> <consumer source dir> <work dir>
set -euo pipefail
build=$1 consumer=$2 work=$3
rm -rf "$work" && mkdir -p "$work"
cmake --install "$build" --prefix "$work/prefix" > "$work/install.log"
cmake -S "$consumer" -B "$work/consumer" -DCMAKE_PREFIX_PATH="$work/prefix" -DCMAKE_BUILD_TYPE=Release > "$work/configure.log"
cmake --build "$work/consumer" -j2 > "$work/build.log"
# the data the MC reads at start: its motions and the user gait files they name
for f in config/motions/02_shake_right_hand.toml config/motions/12_moonwalk.toml config/user_gaits/moonwalk_def.toml; do
  [[ -f "$work/prefix/share/cerebellum/$f" ]] || { echo "not installed: share/cerebellum/$f"; exit 1; }
done
"$work/consumer/consumer" "$work/prefix/share/cerebellum/models/cyberdog2.xml"
