#!/usr/bin/env python3
"""Tests of scripts/polygons_from_ply.py on small PLY files with known polygons."""
import os
import struct
import subprocess
import sys
import tempfile
import unittest

SCRIPT = os.path.join(os.path.dirname(__file__), "..", "..", "scripts", "polygons_from_ply.py")
FAUX = (0x00040000, 0x00080000, 0x00100000)


def write_ply(path, positions, triangles, flags, fmt="ascii", with_flags=True):
    """A PLY with float positions, one extra vertex property, and faces with flags and colour."""
    header = [f"ply", f"format {fmt} 1.0", f"element vertex {len(positions)}", "property float x",
              "property float y", "property float z", "property uchar quality", f"element face {len(triangles)}",
              "property list uchar int vertex_indices"]
    if with_flags:
        header.append("property int flags")
    header += ["property uchar red", "property uchar green", "property uchar blue", "end_header"]
    with open(path, "wb") as out:
        out.write(("\n".join(header) + "\n").encode())
        order = {"binary_little_endian": "<", "binary_big_endian": ">"}.get(fmt)
        for p in positions:
            out.write(struct.pack(order + "fffB", *p, 7) if order else ("%g %g %g 7\n" % p).encode())
        for t, f in zip(triangles, flags):
            if order:
                out.write(struct.pack(order + "B3i", 3, *t) + (struct.pack(order + "i", f) if with_flags else b"")
                          + bytes((1, 2, 3)))
            else:
                out.write(("3 %d %d %d " % tuple(t) + (f"{f} " if with_flags else "") + "1 2 3\n").encode())


def polygons(off_path):
    with open(off_path) as f:
        words = f.read().split()
    assert words[0] == "OFF"
    vertices, faces = int(words[1]), int(words[2])
    at = 4 + 3 * vertices
    result = []
    for _ in range(faces):
        n = int(words[at])
        result.append([int(w) for w in words[at + 1:at + 1 + n]])
        at += 1 + n
    return vertices, result


def cyclic(polygon):
    k = polygon.index(min(polygon))
    return polygon[k:] + polygon[:k]


class PolygonsFromPly(unittest.TestCase):
    def run_script(self, *ply_args, **ply_kwargs):
        directory = tempfile.mkdtemp()
        ply, off = os.path.join(directory, "in.ply"), os.path.join(directory, "out.off")
        write_ply(ply, *ply_args, **ply_kwargs)
        run = subprocess.run([sys.executable, SCRIPT, ply, off], capture_output=True, text=True)
        return run, off

    # A unit square split by its diagonal 0-2, then a triangle 1-4-2 beside it.
    square = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (2, 0.5, 0), (5, 5, 5)]
    triangles = [(0, 1, 2), (0, 2, 3), (1, 4, 2)]

    def test_faux_diagonal_joins_two_triangles_into_a_quad_in_every_format(self):
        flags = [FAUX[2], FAUX[0], 0]  # edge 2 of face 0 is 2->0, edge 0 of face 1 is 0->2
        for fmt in ("ascii", "binary_little_endian", "binary_big_endian"):
            run, off = self.run_script(self.square, self.triangles, flags, fmt)
            self.assertEqual(run.returncode, 0, run.stderr)
            vertices, found = polygons(off)
            self.assertEqual(vertices, 5, "the unused vertex 5 is left out")
            self.assertEqual(sorted(cyclic(p) for p in found), [[0, 1, 2, 3], [1, 4, 2]], fmt)

    def test_without_faux_edges_every_triangle_is_a_polygon(self):
        run, off = self.run_script(self.square, self.triangles, [0, 0, 0])
        self.assertEqual(run.returncode, 0, run.stderr)
        self.assertEqual(len(polygons(off)[1]), 3)

    def test_polygon_starts_at_a_corner_whose_fan_covers_it(self):
        # An L-shaped hexagon listed from corner 0 = (3, 1), whose fan folds (its triangle with
        # corners 1 and 2 turns the wrong way); triangulated as the fan of its reflex corner 1.
        positions = [(3, 1, 0), (1, 1, 0), (1, 3, 0), (0, 3, 0), (0, 0, 0), (3, 0, 0)]
        triangles = [(1, 2, 3), (1, 3, 4), (1, 4, 5), (1, 5, 0)]
        flags = [FAUX[2], FAUX[0] | FAUX[2], FAUX[0] | FAUX[2], FAUX[0]]
        run, off = self.run_script(positions, triangles, flags)
        self.assertEqual(run.returncode, 0, run.stderr)
        (polygon,) = polygons(off)[1]
        self.assertEqual(cyclic(polygon), [0, 1, 2, 3, 4, 5])
        self.assertEqual(polygon[0], 1)
        self.assertNotIn("not fans", run.stdout)

    def test_missing_flags_and_a_ring_are_errors(self):
        run, _ = self.run_script(self.square, self.triangles, [0, 0, 0], with_flags=False)
        self.assertEqual(run.returncode, 1)
        self.assertIn("no face flags", run.stderr)
        # A square ring of 8 triangles around a square hole, every inner edge faux: one group
        # with two outlines, which no polygon can be.
        outer = [(0, 0, 0), (3, 0, 0), (3, 3, 0), (0, 3, 0)]
        inner = [(1, 1, 0), (2, 1, 0), (2, 2, 0), (1, 2, 0)]
        triangles, flags = [], []
        for i in range(4):
            a, b, c, d = i, (i + 1) % 4, 4 + (i + 1) % 4, 4 + i
            triangles += [(a, b, c), (a, c, d)]
            flags += [FAUX[2], FAUX[0] | FAUX[2]]  # c->a shared; a->d joins the next quad
        run, _ = self.run_script(outer + inner, triangles, flags)
        self.assertEqual(run.returncode, 1)
        self.assertIn("more than one loop", run.stderr)


if __name__ == "__main__":
    unittest.main()
