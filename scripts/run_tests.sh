#!/usr/bin/env bash
# Installs what is needed, builds, and runs every test: vcg_core unit tests, the end-to-end
# tests through the real meshlabserver (and the MeshLab GUI) under Xvfb, pymeshlab's, then the
# unit tests and the fuzz replay again under ASan and UBSan. Arguments go to ctest.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
bash "$root/scripts/build.sh"
# The sanitized build runs beside CTest at the lowest priority: CTest's GUI and meshlabserver
# tests run one at a time (RESOURCE_LOCK xvfb) and leave a core idle for much of their run. In a
# process group of its own (set -m), so that a failed CTest stops it and its compilers; in the
# same session, whose scheduling group nice is relative to.
set -m
nice -n 19 bash "$root/scripts/build_sanitized.sh" > "$root/build-sanitize.log" 2>&1 &
sanitized_build=$!
set +m
trap 'kill -- -"$sanitized_build" 2>/dev/null || true' EXIT
(cd "$root/build" && ctest --output-on-failure -j2 "$@")
wait "$sanitized_build" || { cat "$root/build-sanitize.log"; exit 1; }
trap - EXIT
# bunny00's meshing sweep, the longest sanitized test, runs in CTest above only: the sweep's
# seven other meshes take the same paths under the sanitizers, and CI's first run is short of time.
bash "$root/scripts/run_sanitized_tests.sh" -E 'MeshingSweep\.RealMesh/bunny00 '
