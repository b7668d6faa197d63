#!/usr/bin/env python3
"""Converts an STL (ASCII or binary) to OFF, welding vertices with identical coordinates.

    bench/stl_to_off.py IN.stl OUT.off            # welded: one vertex per distinct point
    bench/stl_to_off.py --unwelded IN.stl OUT.off # every triangle its own three vertices

STL repeats each vertex in every triangle that uses it; OpenSCAD writes a shared point with the
same digits each time, so exact equality welds its output into a connected mesh (no tolerance
that could merge distinct points of fine features). Triangles left with a repeated vertex have no
area and are dropped. Prints one JSON line: vertices, faces, dropped. Standard library only.
"""

import argparse
import json
import struct


def read_stl(path):
    """The triangles, as triples of (x, y, z) tuples."""
    with open(path, "rb") as f:
        data = f.read()
    if data.lstrip().startswith(b"solid") and b"facet" in data[:1000]:
        coords = [tuple(float(v) for v in line.split()[1:4])
                  for line in data.decode("ascii").splitlines() if line.strip().startswith("vertex")]
        return [coords[i:i + 3] for i in range(0, len(coords), 3)]
    (count,) = struct.unpack_from("<I", data, 80)
    triangles = []
    for t in range(count):
        values = struct.unpack_from("<12f", data, 84 + 50 * t)
        triangles.append([values[3:6], values[6:9], values[9:12]])
    return triangles


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--unwelded", action="store_true", help="keep every triangle's own vertices")
    parser.add_argument("stl")
    parser.add_argument("off")
    args = parser.parse_args()

    vertices, index, faces, dropped = [], {}, [], 0
    for triangle in read_stl(args.stl):
        face = []
        for point in triangle:
            if args.unwelded or point not in index:
                index[point] = len(vertices)
                vertices.append(point)
            face.append(len(vertices) - 1 if args.unwelded else index[point])
        if len(set(face)) < 3:
            dropped += 1
        else:
            faces.append(face)
    with open(args.off, "w") as f:
        f.write("OFF\n%d %d 0\n" % (len(vertices), len(faces)))
        f.writelines("%r %r %r\n" % v for v in vertices)
        f.writelines("3 %d %d %d\n" % tuple(face) for face in faces)
    print(json.dumps({"off": args.off, "vertices": len(vertices), "faces": len(faces), "dropped": dropped}))


if __name__ == "__main__":
    main()
