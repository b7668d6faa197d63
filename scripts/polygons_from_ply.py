#!/usr/bin/env python3
"""Writes the polygons of a VSA approximation as an OFF file, from the PLY that MeshLab saved
with face flags (meshlabserver `-m ff`, or the Flags box of the GUI's PLY export).

The filter's polygonal output marks the edges inside each polygon faux (vcg face flags FAUX0-2,
edge i joining corners i and i+1). MeshLab 2020.09 cannot save those polygons itself: its OFF
export with `-m mp` writes each vertex's flags where the vertex index belongs (vcglib
wrap/io_trimesh/export_off.h, fixed in later releases), and meshlabserver cannot ask for
polygonal OBJ. This script joins the triangles across faux edges, walks each polygon's outline
and writes the polygons, on the vertices they use, as OFF, each from a corner whose fan covers
it where there is one, for readers that triangulate a polygon as the fan of its first corner; it
warns that MeshLab 2025.07 misreads polygons of 5 corners or more in OFF. It stops with an
error if a polygon is not a disc with one outline, or if the PLY has no face flags.

    python3 scripts/polygons_from_ply.py APPROXIMATION.ply POLYGONS.off
"""
import struct
import sys

FAUX = (0x00040000, 0x00080000, 0x00100000)
SCALARS = {  # PLY type -> struct code
    "char": "b", "int8": "b", "uchar": "B", "uint8": "B", "short": "h", "int16": "h",
    "ushort": "H", "uint16": "H", "int": "i", "int32": "i", "uint": "I", "uint32": "I",
    "float": "f", "float32": "f", "double": "d", "float64": "d",
}


def read_ply(path):
    """Vertex positions, triangles and per-face flags of a PLY file (ascii or binary)."""
    with open(path, "rb") as f:
        data = f.read()
    end = data.find(b"end_header")
    if not data.startswith(b"ply") or end < 0:
        raise ValueError(f"{path} is not a PLY file")
    body = data.index(b"\n", end) + 1
    fmt, elements = None, []
    for line in data[:end].decode("ascii", "replace").splitlines():
        words = line.split()
        if not words:
            continue
        if words[0] == "format":
            fmt = words[1]
        elif words[0] == "element":
            elements.append((words[1], int(words[2]), []))
        elif words[0] == "property" and elements:
            elements[-1][2].append((words[-1], words[1:-1]))
    if fmt not in ("ascii", "binary_little_endian", "binary_big_endian"):
        raise ValueError(f"{path}: unknown PLY format {fmt}")
    order = "<" if fmt == "binary_little_endian" else ">"
    tokens = iter(data[body:].split()) if fmt == "ascii" else None
    offset = body

    def scalar(kind):
        nonlocal offset
        if tokens is not None:
            text = next(tokens)
            return float(text) if SCALARS[kind] in "fd" else int(text)
        code = order + SCALARS[kind]
        (value,) = struct.unpack_from(code, data, offset)
        offset += struct.calcsize(code)
        return value

    positions, triangles, flags = [], [], []
    for name, count, properties in elements:
        for _ in range(count):
            record = {}
            for prop, kind in properties:
                if kind[0] == "list":
                    record[prop] = [scalar(kind[2]) for _ in range(scalar(kind[1]))]
                else:
                    record[prop] = scalar(kind[0])
            if name == "vertex":
                positions.append((record["x"], record["y"], record["z"]))
            elif name == "face":
                corners = record.get("vertex_indices", record.get("vertex_index"))
                if corners is None or len(corners) != 3:
                    raise ValueError(f"{path}: faces must be triangles")
                if "flags" not in record:
                    raise ValueError(f"{path} has no face flags: save it with them (meshlabserver -m ff)")
                triangles.append(corners)
                flags.append(record["flags"])
    return positions, triangles, flags


def polygons_of(triangles, flags):
    """The outlines of the groups of triangles joined through faux edges, in order of each
    group's first triangle."""
    parent = list(range(len(triangles)))

    def root(t):
        while parent[t] != t:
            parent[t] = parent[parent[t]]
            t = parent[t]
        return t

    face_of_edge = {}
    for t, (a, b, c) in enumerate(triangles):
        for u, v in ((a, b), (b, c), (c, a)):
            face_of_edge[(u, v)] = t
    for t, corners in enumerate(triangles):
        for i in range(3):
            if flags[t] & FAUX[i]:
                across = face_of_edge.get((corners[(i + 1) % 3], corners[i]))
                if across is None:
                    raise ValueError(f"triangle {t}: faux edge {i} on the border")
                parent[root(t)] = root(across)
    outline = {}  # group -> {start vertex: end vertex} of its outline edges
    for t, corners in enumerate(triangles):
        for i in range(3):
            u, v = corners[i], corners[(i + 1) % 3]
            across = face_of_edge.get((v, u))
            if across is not None and root(across) == root(t):
                continue
            next_of = outline.setdefault(root(t), {})
            if u in next_of:
                raise ValueError(f"polygon of triangle {t} touches itself at vertex {u}")
            next_of[u] = v
    polygons = []
    for group, next_of in outline.items():
        start = min(next_of)
        loop = [start]
        while next_of[loop[-1]] != start:
            loop.append(next_of[loop[-1]])
            if len(loop) > len(next_of):
                raise ValueError(f"polygon of triangle {group}: its outline does not close")
        if len(loop) != len(next_of):
            raise ValueError(f"polygon of triangle {group} has {len(next_of)} outline edges in more than one loop")
        polygons.append(loop)
    if len(polygons) != len({root(t) for t in range(len(triangles))}):
        raise ValueError("a polygon has no outline (a closed surface of faux edges)")
    return polygons


def sub(p, q):
    return (p[0] - q[0], p[1] - q[1], p[2] - q[2])


def cross(u, v):
    return (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])


def dot(u, v):
    return u[0] * v[0] + u[1] * v[1] + u[2] * v[2]


def fan_ready(loop, positions):
    """`loop` started at a corner whose fan triangulates it without folding (every fan triangle
    turns like the polygon's Newell normal), and whether there is one: for readers that
    triangulate each polygon as a fan from its first corner."""
    points = [positions[v] for v in loop]
    normal = [0.0, 0.0, 0.0]
    for i, p in enumerate(points):
        q = points[(i + 1) % len(points)]
        normal[0] += (p[1] - q[1]) * (p[2] + q[2])
        normal[1] += (p[2] - q[2]) * (p[0] + q[0])
        normal[2] += (p[0] - q[0]) * (p[1] + q[1])
    n = len(loop)
    for apex in range(n):
        a = points[apex]
        if all(dot(cross(sub(points[(apex + k) % n], a), sub(points[(apex + k + 1) % n], a)), normal) > 0
               for k in range(1, n - 1)):
            return loop[apex:] + loop[:apex], True
    return loop, False


def main():
    if len(sys.argv) != 3:
        print(__doc__, file=sys.stderr)
        return 2
    source, target = sys.argv[1:]
    try:
        positions, triangles, flags = read_ply(source)
        polygons = polygons_of(triangles, flags)
    except (OSError, ValueError, KeyError, StopIteration, struct.error) as error:
        print(f"polygons_from_ply: {error}", file=sys.stderr)
        return 1
    ready = [fan_ready(polygon, positions) for polygon in polygons]
    polygons = [polygon for polygon, _ in ready]
    used = sorted({v for polygon in polygons for v in polygon})
    index = {v: i for i, v in enumerate(used)}
    with open(target, "w") as out:
        out.write(f"OFF\n{len(used)} {len(polygons)} 0\n")
        for v in used:
            out.write("%.9g %.9g %.9g\n" % positions[v])
        for polygon in polygons:
            out.write(f"{len(polygon)} " + " ".join(str(index[v]) for v in polygon) + "\n")
    quads = sum(len(p) == 4 for p in polygons)
    print(f"{target}: {len(polygons)} polygons ({quads} quadrilaterals, the largest with "
          f"{max(len(p) for p in polygons)} sides) on {len(used)} vertices, from {len(triangles)} triangles")
    folding = sum(not fine for _, fine in ready)
    if folding:
        print(f"  {folding} polygons are not fans of any corner: readers that triangulate each polygon as a "
              "fan fold them")
    if any(len(p) >= 5 for p in polygons):
        print("  MeshLab 2025.07 and pymeshlab 2025.7 misread polygons of 5 corners or more in OFF "
              "(MeshLab issue #1664): open the PLY there")
    return 0


if __name__ == "__main__":
    sys.exit(main())
