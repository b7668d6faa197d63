#!/usr/bin/env bash
# Installs pymeshlab from PyPI into the project's own virtual environment (.venv, git-ignored) and
# describes the MeshLab inside the wheel for CMake, so that the plugin is built for it. Idempotent.
#  - .venv with tests/pymeshlab/requirements.txt (pymeshlab 2025.7.post1, numpy, pytest)
#  - .deps/pymeshlab/meshlab-build-info.cmake: the wheel's MESHLAB_VERSION ("2025.07d": double
#    precision) and its libmeshlab-common.so, with the headers of the same MeshLab release from
#    Debian's source package (scripts/setup_filterplugin.sh). The plugin links to the wheel's own
#    library, so pymeshlab's MeshLab is never built here.
# Pass .deps/pymeshlab to CMake as -DVSA_FILTERPLUGIN_MESHLAB_DIR (scripts/build.sh does).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
venv="$root/.venv"
requirements="$root/tests/pymeshlab/requirements.txt"
tree="$root/.deps/pymeshlab"

source "$root/scripts/lib/apt_packages.sh"
install_missing_packages setup_pymeshlab python3 python3-venv
if [ "$(cat "$venv/.vsa-requirements" 2>/dev/null)" != "$(sha256sum < "$requirements")" ]; then
  echo "setup_pymeshlab: installing $(grep -v '^#' "$requirements" | tr '\n' ' ')into ${venv#"$root"/}"
  rm -rf "$venv"
  python3 -m venv "$venv"
  "$venv/bin/pip" install -q --disable-pip-version-check -r "$requirements"
  sha256sum < "$requirements" > "$venv/.vsa-requirements"
fi

# What the wheel says of itself: "PyMeshLab 2025.7.post1 based on MeshLab 2025.07d".
wheel=$("$venv/bin/python" -c 'import os, pymeshlab; print(os.path.dirname(pymeshlab.__file__))')
banner=$("$venv/bin/python" -c 'import pymeshlab; pymeshlab.print_pymeshlab_version()')
version=$(sed -n 's/.*based on MeshLab \([^ ]*\).*/\1/p' <<< "$banner")
[ -n "$version" ] || { echo "setup_pymeshlab: cannot read the MeshLab version from '$banner'" >&2; exit 1; }
scalar=float
[ "${version: -1}" = d ] && scalar=double

# The headers must be those of the release the wheel was built from: MeshLab's own plugin check
# compares only the first 6 characters of the version, so a mismatch would load and misbehave.
src="$root/.deps/meshlab-modern/current/src"
[ -f "$src/ML_VERSION" ] || VSA_FILTERPLUGIN_SOURCES_ONLY=1 bash "$root/scripts/setup_filterplugin.sh"
headers=$(tr -d '[:space:]' < "$src/ML_VERSION")
if [ "$headers" != "${version%d}" ]; then
  echo "setup_pymeshlab: the wheel's MeshLab is $version, the headers in ${src#"$root"/} are $headers" >&2
  exit 1
fi

mkdir -p "$tree"
cat > "$tree/meshlab-build-info.cmake.new" <<EOT
# Written by scripts/setup_pymeshlab.sh: the MeshLab inside the pymeshlab wheel ($banner).
set(MESHLAB_FP_HOST "pymeshlab")
set(MESHLAB_FP_ORIGIN_TEXT "$banner, $wheel")
set(MESHLAB_FP_VERSION "$version")
set(MESHLAB_FP_SCALAR "$scalar")
set(MESHLAB_FP_SOURCE_DIR "$src/src")
set(MESHLAB_FP_VCGLIB_DIR "$src/src/vcglib")
set(MESHLAB_FP_COMMON_LIBRARY "$wheel/lib/libmeshlab-common.so")
set(MESHLAB_FP_PLUGIN_DIR "$wheel/lib/plugins")
set(MESHLAB_FP_PYTHON "$venv/bin/python")
EOT
# Rewritten only when it changes, so that CMake does not reconfigure for nothing.
if cmp -s "$tree/meshlab-build-info.cmake.new" "$tree/meshlab-build-info.cmake"; then
  rm "$tree/meshlab-build-info.cmake.new"
else
  mv "$tree/meshlab-build-info.cmake.new" "$tree/meshlab-build-info.cmake"
fi
echo "setup_pymeshlab: ready: $banner (MeshLab $version, $scalar) in ${venv#"$root"/}"
