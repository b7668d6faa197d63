#!/usr/bin/env bash
# A libFuzzer campaign over ApproximateShape (approximate_shape_fuzz.cpp) under ASan and UBSan:
#   bash tests/fuzz/run_campaign.sh [SECONDS]      (default 600; one process)
# Builds build-fuzz/ with clang (installed here if missing), then fuzzes from the seeds, the
# regressions and the corpus grown by earlier campaigns (tests/fuzz/corpus/, git-ignored).
# A crash or broken postcondition leaves its input in tests/fuzz/artifacts/ (git-ignored): once
# fixed, copy it into tests/fuzz/regressions/, which the unit tests replay
# (FuzzInputs.SeedsAndRegressionsReplayWithoutFinding).
# The last lines are libFuzzer's final stats (runs, coverage); the whole log is in
# build-fuzz/campaign.log.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
seconds=${1:-600}
source "$root/scripts/lib/apt_packages.sh"
install_missing_packages fuzz clang libclang-rt-14-dev
bash "$root/scripts/setup.sh" > /dev/null
build="$root/build-fuzz"
mkdir -p "$build"
CC=clang CXX=clang++ cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DVSA_FUZZ=ON \
  -DVSA_FILTERPLUGIN_MESHLAB_DIR= > "$build/build.log" 2>&1 || { cat "$build/build.log"; exit 1; }
cmake --build "$build" --target vsa_fuzz -j2 >> "$build/build.log" 2>&1 || { tail -50 "$build/build.log"; exit 1; }
fuzz="$root/tests/fuzz"
mkdir -p "$fuzz/corpus" "$fuzz/artifacts"
"$build/tests/fuzz/vsa_fuzz" -max_total_time="$seconds" -max_len=600 -timeout=60 -print_final_stats=1 \
  -artifact_prefix="$fuzz/artifacts/" "$fuzz/corpus" "$fuzz/seeds" "$fuzz/regressions" \
  > "$build/campaign.log" 2>&1 || status=$?
grep -E "^(#[0-9]+.*(DONE|pulse|NEW|REDUCE)|stat::|Done )" "$build/campaign.log" | tail -15
grep -A30 -E "ERROR: |broken postcondition|runtime error" "$build/campaign.log" | head -60 || true
exit "${status:-0}"
