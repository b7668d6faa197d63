#!/usr/bin/env bash
# The unit tests of vcg_core and of the bench's helpers, and the replay of the fuzz seeds and
# regressions under AddressSanitizer and UndefinedBehaviorSanitizer (-fno-sanitize-recover: any
# finding fails the run), built in build-sanitize/. Arguments go to ctest (e.g. -R Meshing).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
bash "$root/scripts/setup.sh"
build="$root/build-sanitize"
mkdir -p "$build"
# -O1, the usual level under ASan: quicker to build than the -O3 of Release.
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_FLAGS_RELEASE="-O1 -DNDEBUG" \
  -DVSA_SANITIZE=ON -DVSA_FILTERPLUGIN_MESHLAB_DIR= \
  > "$build/build.log" 2>&1 || { cat "$build/build.log"; exit 1; }
cmake --build "$build" -j2 --target vsa_unit_tests vsa_bench_helper_tests >> "$build/build.log" 2>&1 \
  || { tail -50 "$build/build.log"; exit 1; }
cd "$build"
# One process per test, two at a time: under the sanitizers the tests take minutes, and a few
# of them most of it, which CTest hands out as the cores free up (gtest's shards split by count).
ctest -j2 -L '^unit$' --no-tests=error --output-on-failure "$@" > "$build/ctest.log" 2>&1 \
  || { grep -v -E '^ +Start |Passed +[0-9.]+ sec$' "$build/ctest.log" | tail -n 300
       echo "sanitized tests: failed (log: $build/ctest.log)" >&2; exit 1; }
grep -E "tests passed|Total Test time" "$build/ctest.log"
echo "sanitized tests: passed"
