#!/usr/bin/env bash
# Downloads the upstream (orig) tarball of one of Debian's source packages into a folder and prints
# its path. Usage: scripts/debian_orig_tarball.sh <source package> <Debian version> <folder>
# e.g. scripts/debian_orig_tarball.sh lcm 1.3.1+repack1-3 /tmp/lcm
# For what Debian packages without the piece we need (LCM's Python module, a static liblcm.a or
# libalglib.a for the robot's build): the sources stay Debian's. A deb-src list of our own is used
# only for this download, so apt's system lists stay as they are. Only the orig tarball is taken:
# the Debian patch archive may be missing on a mirror.
set -euo pipefail
if [[ $# -ne 3 ]]; then
  echo "usage: $0 <source package> <Debian version> <folder>" >&2
  exit 2
fi
package=$1 version=$2 folder=$3
upstream=${version%-*}  # 1.3.1+repack1-3 -> 1.3.1+repack1
mkdir -p "$folder"
existing=$(ls "$folder/${package}_$upstream".orig.tar.* 2>/dev/null | head -1 || true)
if [[ -n "$existing" ]]; then
  echo "$existing"
  exit 0
fi
work=$(mktemp -d)
chmod 755 "$work"  # apt downloads as _apt
trap 'rm -rf "$work"' EXIT
mkdir -p "$work/parts" "$work/lists/partial" "$work/download"
chmod 777 "$work/download"
cat > "$work/parts/debian-src.sources" <<SOURCES
Types: deb-src
URIs: http://deb.debian.org/debian
Suites: $(. /etc/os-release && echo "$VERSION_CODENAME")
Components: main
Signed-By: /usr/share/keyrings/debian-archive-keyring.gpg
SOURCES
apt_opts=(-o Dir::Etc::SourceList=/dev/null -o "Dir::Etc::SourceParts=$work/parts"
          -o "Dir::State::Lists=$work/lists" -o Dir::Cache::pkgcache= -o Dir::Cache::srcpkgcache=)
apt-get "${apt_opts[@]}" -qq update
(cd "$work/download" && apt-get "${apt_opts[@]}" -qq source --download-only "$package=$version" >/dev/null 2>&1) || true
tarball=$(ls "$work/download/${package}_$upstream".orig.tar.* 2>/dev/null | head -1 || true)
if [[ -z "$tarball" ]]; then
  echo "debian_orig_tarball: could not download the orig tarball of Debian's $package $version" >&2
  exit 1
fi
mv "$tarball" "$folder/"
echo "$folder/$(basename "$tarball")"
