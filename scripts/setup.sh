#!/usr/bin/env bash
# Installs everything the build, the tests and the sample run need; idempotent.
#  - Debian packages (MeshLab 2020.09, Qt, Eigen, GoogleTest, CGAL, Xvfb, ...)
#  - MeshLab's headers and vcglib, from Debian's `meshlab` source package of exactly the
#    installed version, fetched through a private apt configuration into .deps/
#  - CGAL's sample meshes (package libcgal-demo) into .deps/cgal-data, for tests and benchmarks
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
deps="$root/.deps"
mkdir -p "$deps"

packages=(meshlab qtbase5-dev libqt5opengl5-dev libqt5xmlpatterns5-dev libglew-dev libeigen3-dev
          libgtest-dev cmake g++ make xvfb xauth dpkg-dev libcgal-dev libgmp-dev libmpfr-dev
          libboost-dev x11-apps xdotool imagemagick tesseract-ocr tesseract-ocr-eng python3 ca-certificates)
source "$root/scripts/lib/apt_packages.sh"
install_missing_packages setup "${packages[@]}"

apt_private=(-o Dir::Etc::SourceList=/dev/null
             -o Dir::Etc::SourceParts="$root/scripts/apt-sources"
             -o Dir::State::Lists="$deps/apt-lists"
             -o Dir::Cache="$deps/apt-cache")

# MeshLab headers + vcglib: the source package of the installed binary version.
ml_version=$(dpkg-query -W -f='${Version}' meshlab)
ml_src="$deps/meshlab-src"
if [ "$(cat "$ml_src/.version" 2>/dev/null)" != "$ml_version" ]; then
  echo "setup: fetching Debian source package meshlab=$ml_version"
  mkdir -p "$deps/apt-lists/partial" "$deps/apt-cache" "$deps/download"
  apt-get "${apt_private[@]}" update -qq
  rm -rf "$deps/download"/* "$ml_src"
  (cd "$deps/download" && apt-get "${apt_private[@]}" source --download-only -qq "meshlab=$ml_version" 2>&1 \
     | grep -v "unsandboxed" || true)
  # dpkg-source checks every file of the package against the checksums of the .dsc,
  # which apt verified against Debian's signed Release file.
  # (Its gpg warning is expected: Debian's developer keys are not installed, the apt chain is.)
  dpkg-source -x "$deps/download"/meshlab_*.dsc "$ml_src" > "$deps/dpkg-source.log" 2>&1 \
    || { cat "$deps/dpkg-source.log"; exit 1; }
  rm -f "$deps"/meshlab_*.orig.tar.*
  test -f "$ml_src/src/common/interfaces.h" -a -f "$ml_src/vcglib/vcg/complex/complex.h"
  # Debian's rules generate this header at configure time; MeshLab's headers include it.
  echo "static constexpr auto VERSION_STRING = \"${ml_version%%+*}\";" > "$ml_src/src/common/generated_version_header.h"
  echo "$ml_version" > "$ml_src/.version"
fi

# CGAL's data meshes (real test and benchmark meshes).
cgal_data="$deps/cgal-data"
if [ ! -f "$cgal_data/meshes/fandisk.off" ]; then
  echo "setup: fetching libcgal-demo for CGAL's sample meshes"
  mkdir -p "$deps/download-cgal" "$cgal_data"
  (cd "$deps/download-cgal" && rm -f ./*.deb && apt-get download -qq libcgal-demo 2>&1 | grep -v "unsandboxed" || true)
  dpkg-deb --fsys-tarfile "$deps/download-cgal"/libcgal-demo_*.deb \
    | tar -xO ./usr/share/doc/libcgal-dev/data.tar.gz | tar -xz -C "$cgal_data" --strip-components=1 data/meshes
  rm -rf "$deps/download-cgal"
fi
echo "setup: ready (MeshLab $ml_version, sources in .deps/meshlab-src)"
