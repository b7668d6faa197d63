#!/bin/sh
# Makes the large benchmark meshes: CGAL's armadillo Loop-subdivided 1, 2 and 3 times (208k,
# 832k and 3.3M faces) into out/large/ (git-ignored). Needs the loop-subdivide target:
#   cmake --build build --target loop-subdivide
# LOOP_SUBDIVIDE names another binary, VSA_MESHES another folder of sample meshes.
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
tool=${LOOP_SUBDIVIDE:-$root/build/bench/loop-subdivide}
meshes=${VSA_MESHES:-$root/.deps/cgal-data/meshes}
mkdir -p "$root/out/large"
for steps in 1 2 3; do
    out="$root/out/large/armadillo-loop$steps.off"
    [ -s "$out" ] || "$tool" "$meshes/armadillo.off" "$out" "$steps"
done
