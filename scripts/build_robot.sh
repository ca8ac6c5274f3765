#!/usr/bin/env bash
# Cross-builds the MC for the robot's board (the CyberDog2's NX: aarch64, Ubuntu 20.04, glibc 2.31)
# into build-aarch64/: without the simulator (CEREBELLUM_WITH_SIM=OFF) and fully static, so that
# the binary needs nothing of the board's libraries, then checks that it is. docs/robot-build.md.
# Usage: scripts/build_robot.sh [cmake targets...]   (default: everything, the tests included)
# Installs what it needs (root, or sudo) and is safe to run twice: what is present is skipped.
# Builds with nice -n 19 and -j2 (CEREBELLUM_JOBS to change).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build="$root/build-aarch64"
deps="$build/deps"        # the arm64 libraries: Debian's packages unpacked, Debian's sources built
sysroot="$deps/sysroot"   # all of them as one /usr (cmake/aarch64-linux-gnu.toolchain.cmake)
jobs=${CEREBELLUM_JOBS:-2}
toolchain="$root/cmake/aarch64-linux-gnu.toolchain.cmake"
say() { echo "build_robot: $*"; }
sudo_cmd=()
[[ $(id -u) -eq 0 ]] || sudo_cmd=(sudo)

# installed: Debian's cross toolchain and qemu for the tests, which coexist with the build
# machine's packages; liblcm-dev and libalglib-dev (the build machine's) name the versions of the
# sources built below, liblcm-bin is the build machine's lcm-gen, Eigen is headers only
packages=(crossbuild-essential-arm64 qemu-user-static file binutils liblcm-dev liblcm-bin libalglib-dev libeigen3-dev)
native=$(dpkg --print-architecture)
missing=()
for p in "${packages[@]}"; do
  { dpkg-query -W -f='${Status} ${Architecture}\n' "$p" 2>/dev/null || true; } |
    grep -qE "^install ok installed ($native|all)$" || missing+=("$p")
done
if ((${#missing[@]} > 0)); then
  say "installing ${missing[*]}"
  dpkg --print-foreign-architectures | grep -qx arm64 || "${sudo_cmd[@]}" dpkg --add-architecture arm64
  "${sudo_cmd[@]}" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
mkdir -p "$deps/download"
chmod 777 "$deps/download"  # apt downloads as _apt

# not installed: the arm64 -dev packages with the static archives and headers, downloaded and
# unpacked into the sysroot. Installed, those that are not Multi-Arch: same (libyaml-cpp-dev)
# would replace the build machine's own, which its native build needs
sysroot_packages=(libglib2.0-dev libpcre2-dev libgtest-dev libgmock-dev libyaml-cpp-dev libtomlplusplus-dev)
for p in "${sysroot_packages[@]}"; do
  [[ -f "$deps/unpacked-$p" ]] && continue
  if ! dpkg --print-foreign-architectures | grep -qx arm64; then
    "${sudo_cmd[@]}" dpkg --add-architecture arm64
    "${sudo_cmd[@]}" apt-get update -qq
  fi
  say "unpacking $p:arm64 into $sysroot"
  rm -f "$deps/download/${p}"_*_arm64.deb
  (cd "$deps/download" && apt-get download -qq "$p:arm64")
  dpkg-deb -x "$deps/download/${p}"_*_arm64.deb "$sysroot"
  touch "$deps/unpacked-$p"
done

# LCM's and ALGLIB's libraries, static for arm64, from the orig tarballs of Debian's source
# packages of the build machine's versions (Debian ships only their shared libraries), installed
# into the sysroot as /usr beside the unpacked packages
build_from_debian_source() {  # <source package> <version> <cmake project folder> <-D settings, @TREE@: the sources>
  local package=$1 version=$2 project=$3
  shift 3
  local tarball tree log="$deps/build/$package.log"
  tarball=$("$root/scripts/debian_orig_tarball.sh" "$package" "$version" "$deps/download")
  rm -rf "$deps/src/$package" && mkdir -p "$deps/src/$package" "$deps/build"
  tar -xf "$tarball" -C "$deps/src/$package"
  tree=$(find "$deps/src/$package" -mindepth 1 -maxdepth 1 -type d | head -1)
  if ! { cmake -S "$project" -B "$deps/build/$package" -DCMAKE_TOOLCHAIN_FILE="$toolchain" \
           -DCEREBELLUM_AARCH64_SYSROOT="$sysroot" -DCMAKE_BUILD_TYPE=Release -DCMAKE_INSTALL_PREFIX=/usr \
           -DCMAKE_INSTALL_LIBDIR=lib/aarch64-linux-gnu "${@/@TREE@/$tree}" &&
         nice -n 19 cmake --build "$deps/build/$package" -j"$jobs" &&
         DESTDIR="$sysroot" cmake --install "$deps/build/$package"; } >"$log" 2>&1; then
    tail -30 "$log" >&2
    say "building $package $version failed (the whole log: $log)"
    exit 1
  fi
}
libdir="$sysroot/usr/lib/aarch64-linux-gnu"
if [[ ! -f "$libdir/liblcm.a" ]]; then
  say "building LCM's C library (static, arm64) from Debian's lcm source package"
  lcm_version=$(dpkg-query -W -f='${source:Version}' liblcm-dev)
  build_from_debian_source lcm "$lcm_version" "$root/cmake/lcm_static" -DLCM_SOURCE_DIR=@TREE@ \
    -DLCM_VERSION="${lcm_version%%+*}"
fi
if [[ ! -f "$libdir/libalglib.a" ]]; then
  say "building ALGLIB's QP solver (static, arm64) from Debian's alglib source package (a few minutes, once)"
  build_from_debian_source alglib "$(dpkg-query -W -f='${source:Version}' libalglib-dev)" \
    "$root/cmake/alglib_static" -DALGLIB_SOURCE_DIR=@TREE@
fi

# the MC: no simulator, every program static; lcm-gen and python3 stay the build machine's
launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_C_COMPILER_LAUNCHER=ccache -DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
say "configuring $build"
cmake -S "$root" -B "$build" -DCMAKE_TOOLCHAIN_FILE="$toolchain" -DCMAKE_BUILD_TYPE=Release \
  -DCEREBELLUM_AARCH64_SYSROOT="$sysroot" -DCEREBELLUM_WITH_SIM=OFF -DCEREBELLUM_STATIC=ON \
  -DCEREBELLUM_BUILD_JAVA=OFF "${launcher[@]}" >/dev/null
start=$SECONDS
if [[ $# -gt 0 ]]; then
  for target in "$@"; do nice -n 19 cmake --build "$build" --target "$target" -j"$jobs"; done
else
  nice -n 19 cmake --build "$build" -j"$jobs"
fi
say "built in $((SECONDS - start)) s"

binary="$build/src/cli/cerebellum"
[[ -f "$binary" ]] || { say "no $binary (not among the targets built)"; exit 0; }
"$root/scripts/check_static_binary.sh" "$binary"
say "the robot's binary: $binary ($(du -h "$binary" | cut -f1)); to the board: scp it there (docs/robot-build.md)"
