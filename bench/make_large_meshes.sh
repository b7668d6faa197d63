#!/bin/sh
# Makes the large benchmark meshes: CGAL's armadillo Loop-subdivided 1, 2 and 3 times (208k,
# 832k and 3.3M faces) into out/large/ (git-ignored). Needs the loop-subdivide target:
#   cmake --build build --target loop-subdivide
# --steps N subdivides up to N times instead (4: also the 13.3M-face mesh, about 0.7 GB of OFF).
# Also CAD parts whose creases stay sharp, midpoint-subdivided 3 times (midpoint_subdivide.py):
# CGAL's fandisk (829k faces) and, once bench/make_cad_corpus.sh has made it, the gear (158k).
# LOOP_SUBDIVIDE names another binary, VSA_MESHES another folder of sample meshes.
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
tool=${LOOP_SUBDIVIDE:-$root/build/bench/loop-subdivide}
meshes=${VSA_MESHES:-$root/.deps/cgal-data/meshes}
most=3
if [ $# -gt 0 ]; then
    case "$#:${1:-}:${2:-}" in
    2:--steps:*[!0-9]* | 2:--steps: ) echo "usage: $0 [--steps N]" >&2; exit 2 ;;
    2:--steps:*) most=$2 ;;
    *) echo "usage: $0 [--steps N]" >&2; exit 2 ;;
    esac
fi
mkdir -p "$root/out/large"
steps=1
while [ "$steps" -le "$most" ]; do
    out="$root/out/large/armadillo-loop$steps.off"
    [ -s "$out" ] || "$tool" "$meshes/armadillo.off" "$out" "$steps"
    steps=$((steps + 1))
done
midpoint() {
    out="$root/out/large/$2-mid3.off"
    [ ! -s "$1" ] || [ -s "$out" ] || python3 "$root/bench/midpoint_subdivide.py" "$1" "$out" 3
}
midpoint "$meshes/fandisk.off" fandisk
midpoint "$root/out/cad/gear.off" gear
