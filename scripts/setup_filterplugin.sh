#!/usr/bin/env bash
# Builds the "modern" MeshLab plugin API (FilterPlugin, MeshLab 2022.02+, the API pymeshlab uses)
# next to the project's primary target (bookworm's MeshLab 2020.09, scripts/setup.sh). Idempotent.
#  - Debian packages needed to build MeshLab's libmeshlab-common on bookworm (Qt 5.15, GLEW, ...)
#  - the newest `meshlab` source package of Debian unstable (sid), fetched through a private apt
#    configuration (scripts/apt-sources-sid; /etc/apt is never touched); apt checks the tarball
#    against the Sources index, which it checked against Debian's signed Release file
#  - unpacked into .deps/meshlab-modern/<ML_VERSION>/src, and only `meshlab-common`, the `meshlab`
#    GUI application and two of MeshLab's own plugins (io_base: mesh I/O; filter_measure: a
#    reference filter plugin) built into .deps/meshlab-modern/<ML_VERSION>/build in float, as
#    MeshLab's own releases are (mini build, no optional external libraries), cached by the
#    tarball's sha256 (build/.vsa-stamp): a second run only re-reads apt's index. The application
#    is build/src/distrib/meshlab; it loads its stock plugins from distrib/plugins next to it, and
#    a user's from ~/.local/share/VCG/MeshLab_64bit_fp/MeshLabExtraPlugins/<ML_VERSION>/.
#    pymeshlab's double-precision MeshLab is not built: the plugin for it links to the wheel's own
#    library (scripts/setup_pymeshlab.sh).
#  - .deps/meshlab-modern/current -> <ML_VERSION>; build/meshlab-build-info.cmake and
#    build/meshlab-build-info.txt tell the MESHLAB_VERSION / MESHLAB_SCALAR the build used;
#    cmake/MeshLabFilterPlugin.cmake reads the former (-DVSA_FILTERPLUGIN_MESHLAB_DIR=<build dir>).
# Environment:
#   VSA_FILTERPLUGIN_OFFLINE=1     skip `apt-get update` (use the lists fetched last time)
#   VSA_FILTERPLUGIN_VERSION=V     fetch meshlab=V instead of the newest (e.g. 2025.07~dfsg-4)
#   VSA_FILTERPLUGIN_PLUGINS="io_base filter_measure"   MeshLab plugins to build with the library
#   VSA_FILTERPLUGIN_SOURCES_ONLY=1  fetch and unpack the sources (headers for the pymeshlab build),
#                                  build nothing
#   VSA_FILTERPLUGIN_JOBS=2        build parallelism (the machine is shared: 2 at most)
set -euo pipefail
t0=$(date +%s)
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
deps="$root/.deps"
modern="$deps/meshlab-modern"
mkdir -p "$modern"
jobs=${VSA_FILTERPLUGIN_JOBS:-2}
read -r -a ml_plugins <<< "${VSA_FILTERPLUGIN_PLUGINS:-io_base filter_measure}"

# What meshlab-common 2025.07 needs on bookworm (Qt >= 5.15 Core/Widgets/OpenGL/Xml/Network,
# OpenGL + GLU, GLEW >= 2.0, Eigen 3; vcglib and easyexif come in the tarball).
packages=(cmake g++ make xz-utils qtbase5-dev libqt5opengl5-dev libglew-dev libglu1-mesa-dev
          libgl-dev libeigen3-dev ca-certificates)
source "$root/scripts/lib/apt_packages.sh"
install_missing_packages setup_filterplugin "${packages[@]}"

apt_private=(-o Dir::Etc::SourceList=/dev/null
             -o Dir::Etc::SourceParts="$root/scripts/apt-sources-sid"
             -o Dir::State::Lists="$deps/apt-lists-sid"
             -o Dir::Cache="$deps/apt-cache-sid")
mkdir -p "$deps/apt-lists-sid/partial" "$deps/apt-cache-sid" "$modern/download"
if [ "${VSA_FILTERPLUGIN_OFFLINE:-0}" != 1 ]; then
  apt-get "${apt_private[@]}" update -qq 2>&1 | grep -v "unsandboxed" >&2 \
    || true
fi
showsrc=$(apt-cache "${apt_private[@]}" showsrc meshlab 2>/dev/null || true)
if [ -n "${VSA_FILTERPLUGIN_VERSION:-}" ]; then
  deb_version=$VSA_FILTERPLUGIN_VERSION
else
  deb_version=$(awk '/^Package: /{p=$2} /^Version: /{if (p=="meshlab") print $2}' <<< "$showsrc" | sort -V | tail -1)
fi
[ -n "$deb_version" ] || { echo "setup_filterplugin: no meshlab source package in sid's index" >&2; exit 1; }
upstream=${deb_version%-*}; upstream=${upstream#*:}

# apt-get source skips a file that is already there with the right checksum, and checks a new
# download against the checksums of the Sources index (itself checked against the signed Release).
tarball=$(ls "$modern/download"/meshlab_"$upstream".orig.tar.* 2>/dev/null | head -1 || true)
if [ -z "$tarball" ] || [ "${VSA_FILTERPLUGIN_OFFLINE:-0}" != 1 ]; then
  (cd "$modern/download" \
     && apt-get "${apt_private[@]}" source --download-only --tar-only -qq "meshlab=$deb_version" 2>&1 \
     | grep -v -e "unsandboxed" -e "^NOTICE:" -e "salsa.debian.org" -e "^Please use:" \
              -e "^git clone" -e "to retrieve the latest" -e "^Skipping already downloaded" -e "^\$" >&2 || true)
  tarball=$(ls "$modern/download"/meshlab_"$upstream".orig.tar.* 2>/dev/null | head -1 || true)
  [ -n "$tarball" ] || {
    echo "setup_filterplugin: could not fetch meshlab=$deb_version's tarball from sid" >&2
    exit 1
  }
fi
# Independent re-check against the index apt uses (sha256 of the orig tarball in Checksums-Sha256).
tar_sha=$(sha256sum "$tarball" | cut -d' ' -f1)
index_sha=$(awk -v f="$(basename "$tarball")" \
  '/^Checksums-Sha256:/{s=1; next} /^[^ ]/{s=0} s && $3==f {print $1; exit}' <<< "$showsrc")
if [ "$index_sha" != "$tar_sha" ]; then
  echo "setup_filterplugin: $tarball: sha256 $tar_sha differs from sid's index ($index_sha)" >&2
  exit 1
fi
# Drop tarballs of older versions.
find "$modern/download" -maxdepth 1 -type f ! -name "$(basename "$tarball")" -delete

ml_version=$(tar -xJOf "$tarball" --wildcards --no-wildcards-match-slash '*/ML_VERSION' | tr -d '[:space:]')
[ -n "$ml_version" ] || { echo "setup_filterplugin: no ML_VERSION in $tarball" >&2; exit 1; }
dir="$modern/$ml_version"
src="$dir/src"
plugins_cmake=$(printf 'meshlabplugins/%s;' "${ml_plugins[@]}"); plugins_cmake=${plugins_cmake%;}

if [ "$(cat "$src/.vsa-tarball-sha256" 2>/dev/null)" != "$tar_sha" ]; then
  echo "setup_filterplugin: unpacking $(basename "$tarball") into $src"
  rm -rf "$src" "$dir"/build*
  mkdir -p "$src"
  tar -xJf "$tarball" -C "$src" --strip-components=1
  echo "$tar_sha" > "$src/.vsa-tarball-sha256"
fi

# build_tree BUILD_DIR: meshlab-common, the meshlab application and the chosen plugins, in float.
# A tree built before the application was (libraries only) is configured again and keeps its
# objects: only the application is compiled.
build_tree() {
  local scalar=float build=$1
  local stamp_want="$tar_sha $deb_version scalar=$scalar plugins=$plugins_cmake app=meshlab"
  [ "$(cat "$build/.vsa-stamp" 2>/dev/null)" = "$stamp_want" ] && return 0
  echo "setup_filterplugin: building meshlab-common and meshlab $ml_version ($scalar)" \
       "from Debian meshlab $deb_version (sha256 $tar_sha) into $build"
  rm -f "$build/.vsa-stamp"
  mkdir -p "$build"
  local tb; tb=$(date +%s)
  cmake -S "$src" -B "$build" -G "Unix Makefiles" -DCMAKE_BUILD_TYPE=Release \
        -DMESHLAB_BUILD_MINI=ON -DMESHLAB_ALLOW_OPTIONAL_EXTERNAL_LIBRARIES=OFF \
        -DMESHLAB_BUILD_ONLY_LIBRARIES=OFF -DMESHLAB_BUILD_WITH_DOUBLE_SCALAR=OFF \
        -DMESHLAB_PLUGINS="$plugins_cmake" > "$build/vsa-configure.log" 2>&1 \
    || { tail -40 "$build/vsa-configure.log"; exit 1; }
  # copy-distrib-files: the shaders the application reads from distrib/shaders.
  cmake --build "$build" -j "$jobs" --target meshlab-common meshlab copy-distrib-files "${ml_plugins[@]}" \
    > "$build/vsa-build.log" 2>&1 \
    || { grep -B2 -A8 -m5 "error" "$build/vsa-build.log" || tail -40 "$build/vsa-build.log"; exit 1; }
  echo "setup_filterplugin: build took $(( $(date +%s) - tb )) s"

  # The defines MeshLab compiled meshlab-common with (PUBLIC: every plugin must use the same).
  local defs b_version b_scalar lib app
  defs=$(grep '^CXX_DEFINES' "$build/src/common/CMakeFiles/meshlab-common.dir/flags.make")
  b_version=$(sed -n 's/.*-DMESHLAB_VERSION=\([^ ]*\).*/\1/p' <<< "$defs")
  b_scalar=$(sed -n 's/.*-DMESHLAB_SCALAR=\([^ ]*\).*/\1/p' <<< "$defs")
  lib="$build/src/distrib/libmeshlab-common.so"
  app="$build/src/distrib/meshlab"
  test -f "$lib" -a -x "$app" -a -n "$b_version" -a "$b_scalar" = "$scalar"
  cat > "$build/meshlab-build-info.cmake" <<EOF
# Written by scripts/setup_filterplugin.sh: how this libmeshlab-common was built.
set(MESHLAB_FP_DEBIAN_VERSION "$deb_version")
set(MESHLAB_FP_TARBALL_SHA256 "$tar_sha")
set(MESHLAB_FP_VERSION "$b_version")
set(MESHLAB_FP_SCALAR "$b_scalar")
set(MESHLAB_FP_SOURCE_DIR "$src/src")
set(MESHLAB_FP_VCGLIB_DIR "$src/src/vcglib")
set(MESHLAB_FP_COMMON_LIBRARY "$lib")
set(MESHLAB_FP_PLUGIN_DIR "$build/src/distrib/plugins")
set(MESHLAB_FP_APPLICATION "$app")
EOF
  cat > "$build/meshlab-build-info.txt" <<EOF
debian_version=$deb_version
tarball=$(basename "$tarball")
tarball_sha256=$tar_sha
MESHLAB_VERSION=$b_version
MESHLAB_SCALAR=$b_scalar
include_dirs=$src/src $src/src/vcglib /usr/include/eigen3
libmeshlab_common=$lib
plugins_dir=$build/src/distrib/plugins
application=$app
EOF
  echo "$stamp_want" > "$build/.vsa-stamp"
}

ln -sfn "$ml_version" "$modern/current"
if [ "${VSA_FILTERPLUGIN_SOURCES_ONLY:-0}" = 1 ]; then
  echo "setup_filterplugin: sources of MeshLab $ml_version (Debian meshlab $deb_version) in ${src#"$root"/}"
  exit 0
fi
build_tree "$dir/build"

# Pass the directory to CMake as -DVSA_FILTERPLUGIN_MESHLAB_DIR=<dir> (scripts/build.sh does).
echo "setup_filterplugin: ready in $(( $(date +%s) - t0 )) s: MeshLab" \
     "$(sed -n 's/^MESHLAB_VERSION=//p' "$dir/build/meshlab-build-info.txt") (float) in ${dir#"$root"/}/build" \
     "from Debian meshlab $deb_version"
