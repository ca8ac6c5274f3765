#!/usr/bin/env bash
# Every test on a fresh machine: install dependencies, build everything, run ctest.
# In CI (CI=true) a skipped test is a failure: every dependency a test may skip without (Java,
# LCM's Python module, the seeds beside the repository) is installed or present there.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/install_deps.sh"
"$root/scripts/build.sh"
cd "$root/build"
set +e
ctest --output-on-failure --timeout 600 -j"$(nproc)" 2>&1 | tee ctest.log
status=${PIPESTATUS[0]}
set -e
if [[ "${CI:-}" == true ]] && grep -q '(Skipped)$' ctest.log; then
  echo "test.sh: tests were skipped in CI (each one's reason is in its output above):"
  grep '(Skipped)$' ctest.log
  exit 1
fi
exit "$status"
