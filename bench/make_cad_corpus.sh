#!/usr/bin/env bash
# Builds the CAD corpus: each bench/cad/*.scad (our own parts) exported to STL by OpenSCAD
# (Debian's `openscad`) and welded into out/cad/<part>.off (git-ignored), plus
# out/cad/unwelded_gear.off, the gear with every triangle its own component (a bad input).
# Prints one JSON line per part (vertices, faces). Usage: bench/make_cad_corpus.sh [PART...]
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
out=$root/out/cad
mkdir -p "$out"
command -v openscad > /dev/null || { echo "make_cad_corpus: install openscad (apt-get install -y openscad)" >&2; exit 1; }
parts=("$@")
[ ${#parts[@]} -gt 0 ] || parts=($(cd "$root/bench/cad" && ls ./*.scad | sed 's|^\./||; s|\.scad$||'))
for part in "${parts[@]}"; do
  # OpenSCAD 2021.01 exports without a display; its log goes to a file, not the terminal.
  openscad -o "$out/$part.stl" "$root/bench/cad/$part.scad" > "$out/$part.log" 2>&1 ||
    { cat "$out/$part.log" >&2; exit 1; }
  python3 "$root/bench/stl_to_off.py" "$out/$part.stl" "$out/$part.off"
done
if [ -f "$out/gear.stl" ]; then
  python3 "$root/bench/stl_to_off.py" --unwelded "$out/gear.stl" "$out/unwelded_gear.off"
fi
