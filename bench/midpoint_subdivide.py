#!/usr/bin/env python3
"""Splits every triangle of an OFF mesh into four at its edges' midpoints, N times.

    bench/midpoint_subdivide.py IN.off OUT.off N

Unlike Loop subdivision it moves no vertex, so a CAD part keeps its flat sides and sharp creases
at 4^N times the faces: the large meshes on which seeding must still keep to creases. Edges
shared by two faces get one midpoint. Prints one JSON line: vertices, faces. Standard library
only.
"""

import argparse
import json

from off_mesh import read_off


def subdivide(vertices, faces):
    """One step: each triangle (a, b, c) into its three corner triangles and the middle one."""
    midpoint = {}

    def middle(a, b):
        key = (min(a, b), max(a, b))
        if key not in midpoint:
            midpoint[key] = len(vertices)
            vertices.append(tuple((p + q) / 2 for p, q in zip(vertices[a], vertices[b])))
        return midpoint[key]

    out = []
    for a, b, c in faces:
        ab, bc, ca = middle(a, b), middle(b, c), middle(c, a)
        out += [(a, ab, ca), (ab, b, bc), (ca, bc, c), (ab, bc, ca)]
    return out


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("off_in")
    parser.add_argument("off_out")
    parser.add_argument("steps", type=int)
    args = parser.parse_args()
    vertices, faces = read_off(args.off_in)
    if any(len(face) != 3 for face in faces):
        raise SystemExit("%s: triangles only" % args.off_in)
    for _ in range(args.steps):
        faces = subdivide(vertices, faces)
    with open(args.off_out, "w") as f:
        f.write("OFF\n%d %d 0\n" % (len(vertices), len(faces)))
        f.writelines("%.9g %.9g %.9g\n" % v for v in vertices)
        f.writelines("3 %d %d %d\n" % t for t in faces)
    print(json.dumps({"vertices": len(vertices), "faces": len(faces)}))


if __name__ == "__main__":
    main()
