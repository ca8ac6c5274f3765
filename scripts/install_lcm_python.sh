#!/usr/bin/env bash
# LCM's Python module for Debian's python3. Debian packages LCM's C, C++, Java and Lua bindings but
# not the Python one, and PyPI is out of reach: build LCM's own lcm-python/ from the orig tarball of
# Debian's `lcm` source package (the version of the installed liblcm-dev, downloaded by
# scripts/debian_orig_tarball.sh) and install it where Debian's python3 finds it. Two fixes to the
# 1.3.1 sources for Python 3.11: assigning to Py_TYPE() is forbidden (Py_SET_TYPE replaces it), and
# "#" argument formats need PY_SSIZE_T_CLEAN with Py_ssize_t lengths (as later LCM releases do).
# Safe to run twice: skips when `import lcm` works.
set -euo pipefail
python=/usr/bin/python3
if "$python" -c "import lcm; lcm.LCM" 2>/dev/null; then
  echo "install_lcm_python: the lcm module is present"
  exit 0
fi
sudo_cmd=()
[[ $(id -u) -eq 0 ]] || sudo_cmd=(sudo)
version=$(dpkg-query -W -f='${source:Version}' liblcm-dev)   # e.g. 1.3.1+repack1-3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
tarball=$("$(dirname "$0")/debian_orig_tarball.sh" lcm "$version" "$work")
tar -xf "$tarball" -C "$work"
src=$(ls -d "$work"/lcm-*/lcm-python)
sed -i 's/Py_TYPE(\(&[A-Za-z_]*\)) = &PyType_Type;/Py_SET_TYPE(\1, \&PyType_Type);/' "$src/module.c"
sed -i -e 's/^\( *\)int \(channellen\|datalen\) = 0;/\1Py_ssize_t \2 = 0;/' \
       -e 's/next_event->channel, next_event->channellen,/next_event->channel, (Py_ssize_t) next_event->channellen,/' \
       -e 's/next_event->data, next_event->datalen)/next_event->data, (Py_ssize_t) next_event->datalen)/' "$src/pyeventlog.c"
sed -i -e 's/^\( *\)int \(chan_len\|datalen\) = 0;/\1Py_ssize_t \2 = 0;/' \
       -e 's/rbuf->data, rbuf->data_size)/rbuf->data, (Py_ssize_t) rbuf->data_size)/' "$src/pylcm.c"
grep -q "Py_SET_TYPE" "$src/module.c" && grep -q "Py_ssize_t chan_len" "$src/pylcm.c" &&
  grep -q "(Py_ssize_t) next_event->datalen" "$src/pyeventlog.c" || { echo "install_lcm_python: the fixes for Python 3.11 did not apply to $src" >&2; exit 1; }
(cd "$src" && CFLAGS=-DPY_SSIZE_T_CLEAN "$python" setup.py -q build_ext --inplace >/dev/null 2>&1)
target=/usr/lib/python3/dist-packages/lcm
"${sudo_cmd[@]}" mkdir -p "$target"
"${sudo_cmd[@]}" install -m 0644 "$src/lcm/__init__.py" "$target/__init__.py"
"${sudo_cmd[@]}" install -m 0755 "$src"/lcm/_lcm*.so "$target/"
"$python" -c "import lcm; lcm.LCM" && echo "install_lcm_python: lcm ${version%-*} installed in $target"
