#!/usr/bin/env python3
"""Variational Shape Approximation of your own mesh with pymeshlab and this project's plugin.

    .venv/bin/python examples/vsa_pymeshlab.py MESH [--k 50] [--metric L2,1|L2]
        [--init Random|Farthest|Hierarchical] [--seed 0] [--out-dir out/pymeshlab] [--plugin PATH]

Loads the plugin into pymeshlab, approximates MESH with k planar regions, prints the filter's
figures and MeshLab's Hausdorff distance both ways, and writes into the output folder:
  <name>_vsa.ply          the approximation (binary PLY, faces coloured by region, with the face
                          flags that mark the edges inside a region: MeshLab shows one polygon each)
  <name>_vsa_polygons.off the approximation as polygons, one per region
  <name>_regions.ply      the input, faces coloured by region, the region index as face quality
The plugin defaults to the build for pymeshlab (build/filter_vsa/meshlab-2025.07d/libfilter_vsa.so,
made by scripts/build.sh) or an unpacked release archive's libfilter_vsa.so named with --plugin.
"""
import argparse
import os
import pathlib
import sys

import pymeshlab

ROOT = pathlib.Path(__file__).resolve().parent.parent
DEFAULT_PLUGIN = ROOT / "build" / "filter_vsa" / "meshlab-2025.07d" / "libfilter_vsa.so"
FILTER = "meshing_variational_shape_approximation"


def parse_arguments():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("mesh", type=pathlib.Path, help="any mesh pymeshlab reads (OFF, PLY, OBJ, STL, ...)")
    parser.add_argument("--k", type=int, default=50, help="number of planar regions (default 50)")
    parser.add_argument("--metric", default="L2,1", choices=["L2,1", "L2"])
    parser.add_argument("--init", default="Hierarchical", choices=["Random", "Farthest", "Hierarchical"])
    parser.add_argument("--seed", type=int, default=0, help="the same seed gives the same output")
    parser.add_argument("--out-dir", type=pathlib.Path, default=pathlib.Path("out/pymeshlab"))
    parser.add_argument("--plugin", type=pathlib.Path,
                        default=pathlib.Path(os.environ.get("VSA_PYMESHLAB_PLUGIN", DEFAULT_PLUGIN)))
    return parser.parse_args()


def write_polygons_off(mesh, path):
    """One polygon per region, from the faux edges the filter marks inside each region."""
    vertices = mesh.vertex_matrix()
    polygons = mesh.polygonal_face_list()
    with open(path, "w") as out:
        out.write(f"OFF\n{len(vertices)} {len(polygons)} 0\n")
        for x, y, z in vertices:
            out.write(f"{x:.9g} {y:.9g} {z:.9g}\n")
        for polygon in polygons:
            out.write(f"{len(polygon)} {' '.join(str(v) for v in polygon)}\n")
    return len(polygons)


def main():
    args = parse_arguments()
    if not args.plugin.is_file():
        sys.exit(f"{args.plugin}: no such plugin; run scripts/build.sh first or give --plugin")
    pymeshlab.load_plugin(str(args.plugin))

    ms = pymeshlab.MeshSet()
    ms.load_new_mesh(str(args.mesh))
    source_id = ms.current_mesh_id()
    try:
        figures = ms.apply_filter(FILTER, proxynum=args.k, metric=args.metric, init=args.init,
                                  randomseed=args.seed)
    except pymeshlab.PyMeshLabException as error:
        sys.exit(f"{args.mesh}: {error}")
    vsa_id = ms.current_mesh_id()

    print(f"{args.mesh.name}: {ms.mesh(vsa_id).label()}")
    for key in sorted(figures):
        print(f"  {key:22} {figures[key]}")
    diagonal = ms.mesh(source_id).bounding_box().diagonal()
    for sampled, target, direction in ((vsa_id, source_id, "approximation -> input"),
                                       (source_id, vsa_id, "input -> approximation")):
        distance = ms.get_hausdorff_distance(sampledmesh=sampled, targetmesh=target)
        print(f"  Hausdorff {direction}: max {distance['max'] / diagonal:.5f}, "
              f"mean {distance['mean'] / diagonal:.6f} of the diagonal")

    args.out_dir.mkdir(parents=True, exist_ok=True)
    name = args.mesh.stem
    ms.set_current_mesh(vsa_id)
    ms.save_current_mesh(str(args.out_dir / f"{name}_vsa.ply"), binary=True, save_face_flag=True,
                         save_face_color=True)
    polygons = write_polygons_off(ms.current_mesh(), args.out_dir / f"{name}_vsa_polygons.off")
    ms.set_current_mesh(source_id)
    ms.save_current_mesh(str(args.out_dir / f"{name}_regions.ply"), binary=True, save_face_color=True,
                         save_face_quality=True)
    print(f"  wrote {name}_vsa.ply, {name}_vsa_polygons.off ({polygons} polygons) and {name}_regions.ply "
          f"to {args.out_dir}")


if __name__ == "__main__":
    main()
