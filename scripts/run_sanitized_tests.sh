#!/usr/bin/env bash
# The unit tests of vcg_core and of the bench's helpers, and the replay of the fuzz seeds and
# regressions under AddressSanitizer and UndefinedBehaviorSanitizer, built in build-sanitize/
# (build_sanitized.sh). Arguments go to ctest (e.g. -R Meshing).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
bash "$root/scripts/build_sanitized.sh"
build="$root/build-sanitize"
cd "$build"
# One process per test, two at a time: under the sanitizers the tests take minutes, and a few
# of them most of it, which CTest hands out as the cores free up (gtest's shards split by count).
ctest -j2 -L '^unit$' --no-tests=error --output-on-failure "$@" > "$build/ctest.log" 2>&1 \
  || { grep -v -E '^ +Start |Passed +[0-9.]+ sec$' "$build/ctest.log" | tail -n 300
       echo "sanitized tests: failed (log: $build/ctest.log)" >&2; exit 1; }
grep -E "tests passed|Total Test time" "$build/ctest.log"
echo "sanitized tests: passed"
