#!/usr/bin/env bash
# Configures and builds everything (vcg_core tests, vsa-bench, the plugin and its private
# MeshLab prefix, and the plugin for MeshLab's FilterPlugin API with its host and tests) in build/.
# Used by run_sample.sh and run_tests.sh. Arguments, if any, are the targets to build.
#   VSA_FILTERPLUGIN_HOSTS="meshlab pymeshlab" (default): FilterPlugin builds for MeshLab 2025.07
#   (float, MeshLab built from Debian's source package) and for the pymeshlab wheel's MeshLab
#   (2025.07d, double; the wheel installed from PyPI into .venv); either word alone for one,
#   "none" for the MeshLab 2020.09 plugin only (no download of MeshLab's newer sources or of pymeshlab).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
bash "$root/scripts/setup.sh"

hosts=${VSA_FILTERPLUGIN_HOSTS:-meshlab pymeshlab}
fp_dirs=""
for host in $hosts; do
  case $host in
    meshlab) bash "$root/scripts/setup_filterplugin.sh"
             fp_dirs+="$root/.deps/meshlab-modern/current/build;" ;;
    pymeshlab) bash "$root/scripts/setup_pymeshlab.sh"
               fp_dirs+="$root/.deps/pymeshlab;" ;;
    none) ;;
    *) echo "build: unknown host '$host' in VSA_FILTERPLUGIN_HOSTS (meshlab, pymeshlab or none)" >&2; exit 1 ;;
  esac
done
cmake -S "$root" -B "$root/build" -DCMAKE_BUILD_TYPE=Release -DVSA_FILTERPLUGIN_MESHLAB_DIR="${fp_dirs%;}" \
  > "$root/build.log" 2>&1 || { cat "$root/build.log"; exit 1; }
targets=()
for target in "$@"; do targets+=(--target "$target"); done
cmake --build "$root/build" -j2 "${targets[@]}" >> "$root/build.log" 2>&1 || { tail -50 "$root/build.log"; exit 1; }
echo "build: done (log in build.log)"
