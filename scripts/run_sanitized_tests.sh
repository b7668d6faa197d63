#!/usr/bin/env bash
# The unit tests of vcg_core and of the bench's helpers, and the replay of the fuzz seeds and
# regressions under AddressSanitizer and UndefinedBehaviorSanitizer (-fno-sanitize-recover: any
# finding fails the run), built in build-sanitize/. Arguments go to both unit test binaries
# (e.g. --gtest_filter=...).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
bash "$root/scripts/setup.sh"
build="$root/build-sanitize"
mkdir -p "$build"
# -O1, the usual level under ASan: quicker to build than the -O3 of Release.
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_FLAGS_RELEASE="-O1 -DNDEBUG" \
  -DVSA_SANITIZE=ON -DVSA_FILTERPLUGIN_MESHLAB_DIR= \
  > "$build/build.log" 2>&1 || { cat "$build/build.log"; exit 1; }
cmake --build "$build" -j2 --target vsa_unit_tests vsa_bench_helper_tests vsa_fuzz_replay >> "$build/build.log" 2>&1 \
  || { tail -50 "$build/build.log"; exit 1; }
cd "$build"
# The unit tests in two shards at once, one per core: under the sanitizers they take minutes.
pids=()
for shard in 0 1; do
  GTEST_TOTAL_SHARDS=2 GTEST_SHARD_INDEX=$shard tests/vsa_unit_tests --gtest_brief=1 "$@" \
    > "unit_tests_shard$shard.log" 2>&1 &
  pids+=($!)
done
failed=0
for shard in 0 1; do
  if ! wait "${pids[$shard]}"; then failed=1; fi
  tail -n 3 "unit_tests_shard$shard.log"
done
if [ "$failed" -ne 0 ]; then
  for shard in 0 1; do grep -E -A 30 'FAILED|ERROR: AddressSanitizer|runtime error' "unit_tests_shard$shard.log" || true; done
  echo "sanitized unit tests: failed (logs: $build/unit_tests_shard0.log, unit_tests_shard1.log)" >&2
  exit 1
fi
tests/vsa_bench_helper_tests --gtest_brief=1 "$@"
tests/fuzz/vsa_fuzz_replay "$root/tests/fuzz/seeds" "$root/tests/fuzz/regressions" 2> fuzz_replay.log \
  || { cat fuzz_replay.log; exit 1; }
echo "sanitized tests: passed"
