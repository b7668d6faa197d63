#!/usr/bin/env bash
# Configures and builds everything (vcg_core tests, vsa-bench, the plugin and its private
# MeshLab prefix, and the plugin for MeshLab's FilterPlugin API with its host and tests) in build/.
# Used by run_sample.sh and run_tests.sh. Arguments, if any, are the targets to build.
#   VSA_FILTERPLUGIN_SCALARS="float double" (default): FilterPlugin builds for MeshLab 2025.07
#   (float) and for pymeshlab's double-precision MeshLab (2025.07d); "float" or "double" for one,
#   "none" for the MeshLab 2020.09 plugin only (no download of MeshLab's newer sources).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
bash "$root/scripts/setup.sh"

scalars=${VSA_FILTERPLUGIN_SCALARS:-float double}
fp_dirs=""
if [ "$scalars" != none ]; then
  VSA_FILTERPLUGIN_SCALARS="$scalars" bash "$root/scripts/setup_filterplugin.sh"
  for scalar in $scalars; do
    case $scalar in
      float) fp_dirs+="$root/.deps/meshlab-modern/current/build;" ;;
      double) fp_dirs+="$root/.deps/meshlab-modern/current/build-double;" ;;
    esac
  done
fi
cmake -S "$root" -B "$root/build" -DCMAKE_BUILD_TYPE=Release -DVSA_FILTERPLUGIN_MESHLAB_DIR="${fp_dirs%;}" \
  > "$root/build.log" 2>&1 || { cat "$root/build.log"; exit 1; }
targets=()
for target in "$@"; do targets+=(--target "$target"); done
cmake --build "$root/build" -j2 "${targets[@]}" >> "$root/build.log" 2>&1 || { tail -50 "$root/build.log"; exit 1; }
echo "build: done (log in build.log)"
