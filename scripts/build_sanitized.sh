#!/usr/bin/env bash
# Builds the unit tests of vcg_core and of the bench's helpers, with the fuzz replay, under
# AddressSanitizer and UndefinedBehaviorSanitizer (-fno-sanitize-recover: any finding fails the
# run) in build-sanitize/. Used by run_sanitized_tests.sh, and by run_tests.sh beside CTest.
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
