#!/usr/bin/env bash
# Installs what is needed, builds, and runs every test: vcg_core unit tests, the end-to-end
# tests through the real meshlabserver (and the MeshLab GUI) under Xvfb, pymeshlab's, then the
# unit tests and the fuzz replay again under ASan and UBSan. Arguments go to ctest.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
bash "$root/scripts/build.sh"
cd "$root/build"
ctest --output-on-failure -j2 "$@"
bash "$root/scripts/run_sanitized_tests.sh"
