#!/usr/bin/env bash
# The main job: Variational Shape Approximation of a sample mesh through the real meshlabserver
# 2020.09 with our plugin, then MeshLab's own Hausdorff Distance both ways; prints a summary.
#   bash scripts/run_sample.sh [MESH] [SCRIPT]
# Defaults: resources/meshes/fandisk.off and resources/scripts/vsa_hausdorff.mlx.
# Writes to out/: <name>_vsa.ply (the approximation, faces coloured by region, with the face
# flags that mark edges inside a region faux), <name>_vsa.off (the same as polygons, one per
# region, by scripts/polygons_from_ply.py), <name>_regions.ply (the input coloured by region,
# region index as face quality) and meshlabserver.log.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
mesh=$(realpath "${1:-$root/resources/meshes/fandisk.off}")
script=$(realpath "${2:-$root/resources/scripts/vsa_hausdorff.mlx}")
# The sample needs only the MeshLab 2020.09 plugin and its private prefix.
VSA_FILTERPLUGIN_HOSTS=${VSA_FILTERPLUGIN_HOSTS:-none} bash "$root/scripts/build.sh" meshlab_prefix

out="$root/out"
mkdir -p "$out"
name=$(basename "${mesh%.*}")
log="$out/meshlabserver.log"
server="$root/build/meshlab-prefix/bin/meshlabserver"
start=$(date +%s.%N)
status=0
# Layer 0 is the input, layer 1 the approximation (the filter adds it after the input).
# meshlabserver 2020.09 logs "Error: trying to save 3 meshes, but only 2 available" when
# there are more -o than layers, and still saves each -o from its -l layer. Its polygonal OFF
# (-m mp) has wrong vertex indices, hence the polygons from the PLY's face flags.
rm -f "$out/${name}_vsa.ply" "$out/${name}_vsa.off"
xvfb-run -a "$server" -i "$mesh" -s "$script" \
  -o "$out/${name}_vsa.ply" -l 1 -m fc ff \
  -o "$out/${name}_regions.ply" -l 0 -m fc fq > "$log" 2>&1 || status=$?
end=$(date +%s.%N)
python3 "$root/scripts/summarize_run.py" --log "$log" --mesh "$mesh" --seconds "$start" "$end" --status "$status"
if [ "$status" -eq 0 ]; then
  python3 "$root/scripts/polygons_from_ply.py" "$out/${name}_vsa.ply" "$out/${name}_vsa.off" \
    | sed '1s/^/  wrote /; 2,$s/^/  /'
fi
exit $status
