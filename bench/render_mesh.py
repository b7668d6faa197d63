#!/usr/bin/env python3
"""Flat-shaded offscreen pictures of OFF meshes, and side-by-side panels of them.

    render_mesh.py --out PANEL.png [--up y|z] [--size PX] [--second-view]
                   INPUT.off[:LABELS][=CAPTION] OTHER.off[:LABELS][=CAPTION] ...

Every mesh is drawn with the first one's camera: an orthographic 3/4 view fitted to it
(from +x, +up and the third axis; --second-view adds a row from the opposite side). Each face
gets one colour from its normal and a fixed light; a face seen from behind is drawn red, so
flipped triangles and folds show. With a labels file (one polygon label per face, as written
by the drivers' --polygon-labels) the outlines between polygons and along borders are drawn
black, edges inside a polygon are not: slivers and shards show as extra outlines.
A z-buffer rasterizer in numpy, written to PNG with Pillow; no randomness, so the same meshes
give the same pixels. Needs bench/requirements-pictures.txt.
"""

import argparse

import numpy as np
from PIL import Image, ImageDraw, ImageFont

import off_mesh

FRONT = np.array([200, 205, 215], float)  # light grey-blue, like MeshLab's default
BACK = np.array([230, 40, 40], float)     # faces seen from behind
AMBIENT = 0.35                            # keeps faces turned from the light readable
THIN_AXIS_LEAN = 0.2                      # smaller leans harder toward a thin axis
MARGIN = 0.06                             # of the panel's side, around the projected box
CAPTION_LINES = 4
LINE_HEIGHT = 12                          # Pillow's default bitmap font is 11 px high


def read_off(path):
    """Vertices (n, 3) and triangles (m, 3) of an OFF file (off_mesh.read_off); polygons are
    split into fans."""
    vertices, faces = off_mesh.read_off(path)
    triangles = [[corners[0], corners[i], corners[i + 1]] for corners in faces for i in range(1, len(corners) - 1)]
    return np.array(vertices, float).reshape(-1, 3), np.array(triangles, int).reshape(-1, 3)


def read_labels(path):
    with open(path) as f:
        return np.array([int(line) for line in f if line.strip()], int)


class Camera:
    """Orthographic 3/4 view of a mesh, its outline fitted into a square of `size` pixels."""

    def __init__(self, vertices, up, size, opposite=False):
        up_axis = {"y": 1, "z": 2}[up]
        third = 2 if up_axis == 1 else 1
        toward = np.zeros(3)  # from the scene toward the viewer
        toward[0], toward[up_axis], toward[third] = 1.0, 0.7, 1.3 if up_axis == 1 else -1.3
        if opposite:
            toward[0], toward[third] = -toward[0], -toward[third]
        # Leaning toward the box's thin axes shows a plate or a blade from its side, not its
        # edge; a box of equal sides keeps the plain 3/4 view.
        extent = vertices.max(axis=0) - vertices.min(axis=0)
        toward = toward / (extent / (np.linalg.norm(extent) or 1.0) + THIN_AXIS_LEAN)
        self.toward = toward / np.linalg.norm(toward)
        world_up = np.eye(3)[up_axis]
        self.right = np.cross(world_up, self.toward)
        self.right /= np.linalg.norm(self.right)
        self.up = np.cross(self.toward, self.right)
        sx, sy = vertices @ self.right, vertices @ self.up
        self.center = np.array([(sx.min() + sx.max()) / 2, (sy.min() + sy.max()) / 2])
        extent = max(sx.max() - sx.min(), sy.max() - sy.min()) or 1.0
        self.scale = size * (1 - 2 * MARGIN) / extent
        self.size = size
        # The light comes from the viewer's upper left, in front.
        light = 0.8 * self.toward + 0.5 * self.up - 0.4 * self.right
        self.light = light / np.linalg.norm(light)

    def project(self, points):
        """Pixel x, pixel y (down), depth (larger is nearer)."""
        x = (points @ self.right - self.center[0]) * self.scale + self.size / 2
        y = self.size / 2 - (points @ self.up - self.center[1]) * self.scale
        return x, y, points @ self.toward


def outline_edges(triangles, labels):
    """Edges between faces of different polygons, on a border or shared by more than two faces."""
    edges = np.sort(np.concatenate([triangles[:, [0, 1]], triangles[:, [1, 2]], triangles[:, [2, 0]]]), axis=1)
    owner = np.tile(np.arange(len(triangles)), 3)
    order = np.lexsort((edges[:, 1], edges[:, 0]))
    edges, owner = edges[order], owner[order]
    _, first, counts = np.unique(edges, axis=0, return_index=True, return_counts=True)
    keep = counts != 2
    two = counts == 2
    keep[two] = labels[owner[first[two]]] != labels[owner[first[two] + 1]]
    return edges[first[keep]]


def render(vertices, triangles, labels, camera):
    """An RGB image (size x size) of the mesh, white background."""
    size = camera.size
    depth = np.full((size, size), -np.inf)
    image = np.full((size, size, 3), 255.0)
    x, y, z = camera.project(vertices)
    a, b, c = vertices[triangles[:, 0]], vertices[triangles[:, 1]], vertices[triangles[:, 2]]
    normals = np.cross(b - a, c - a)
    lengths = np.linalg.norm(normals, axis=1)
    normals = normals / np.where(lengths > 0, lengths, 1)[:, None]
    facing = normals @ camera.toward
    shade = AMBIENT + (1 - AMBIENT) * np.abs(normals @ camera.light)
    colours = np.where((facing >= 0)[:, None], FRONT, BACK) * shade[:, None]
    for t, (i, j, k) in enumerate(triangles):
        xs, ys, zs = x[[i, j, k]], y[[i, j, k]], z[[i, j, k]]
        area = (xs[1] - xs[0]) * (ys[2] - ys[0]) - (xs[2] - xs[0]) * (ys[1] - ys[0])
        if area == 0:
            continue
        x0, x1 = max(int(np.floor(xs.min())), 0), min(int(np.ceil(xs.max())), size - 1)
        y0, y1 = max(int(np.floor(ys.min())), 0), min(int(np.ceil(ys.max())), size - 1)
        if x0 > x1 or y0 > y1:
            continue
        px, py = np.meshgrid(np.arange(x0, x1 + 1) + 0.5, np.arange(y0, y1 + 1) + 0.5)
        w0 = ((xs[1] - px) * (ys[2] - py) - (xs[2] - px) * (ys[1] - py)) / area
        w1 = ((xs[2] - px) * (ys[0] - py) - (xs[0] - px) * (ys[2] - py)) / area
        w2 = 1 - w0 - w1
        inside = (w0 >= 0) & (w1 >= 0) & (w2 >= 0)
        if not inside.any():
            continue
        d = w0 * zs[0] + w1 * zs[1] + w2 * zs[2]
        window = depth[y0:y1 + 1, x0:x1 + 1]
        nearer = inside & (d > window)
        window[nearer] = d[nearer]
        image[y0:y1 + 1, x0:x1 + 1][nearer] = colours[t]
    if labels is not None and len(labels) == len(triangles):
        draw_outlines(image, depth, x, y, z, outline_edges(triangles, labels), camera)
    return Image.fromarray(image.astype(np.uint8))


def draw_outlines(image, depth, x, y, z, edges, camera):
    """Black edges where they are not hidden behind a face (with a little depth slack, as a
    line lies on the faces it bounds)."""
    slack = 2e-3 * camera.size / camera.scale
    for i, j in edges:
        steps = int(max(abs(x[j] - x[i]), abs(y[j] - y[i]))) + 2
        s = np.linspace(0, 1, steps)
        px = np.floor(x[i] + s * (x[j] - x[i])).astype(int)
        py = np.floor(y[i] + s * (y[j] - y[i])).astype(int)
        pz = z[i] + s * (z[j] - z[i])
        ok = (px >= 0) & (px < camera.size) & (py >= 0) & (py < camera.size)
        px, py, pz = px[ok], py[ok], pz[ok]
        visible = pz >= depth[py, px] - slack
        image[py[visible], px[visible]] = 0


def panel(items, out_png, up="y", size=320, second_view=False):
    """items: (off path, labels path or None, caption) per column; the first sets the camera. A
    column without a path (a tool that gave no mesh) shows its caption alone."""
    meshes = [read_off(path) if path else None for path, _, _ in items]
    views = [False, True] if second_view else [False]
    caption_height = CAPTION_LINES * LINE_HEIGHT + 6
    sheet = Image.new("RGB", (size * len(items), size * len(views) + caption_height), "white")
    font = ImageFont.load_default()
    draw = ImageDraw.Draw(sheet)
    for row, opposite in enumerate(views):
        camera = Camera(meshes[0][0], up, size, opposite)
        for column, (mesh, (_, labels_path, _)) in enumerate(zip(meshes, items)):
            if mesh is None:
                continue
            labels = read_labels(labels_path) if labels_path else None
            sheet.paste(render(mesh[0], mesh[1], labels, camera), (column * size, row * size))
    for column, (_, _, caption) in enumerate(items):
        for line_number, line in enumerate(caption.split("\n")[:CAPTION_LINES]):
            draw.text((column * size + 4, size * len(views) + 3 + line_number * LINE_HEIGHT), line, fill="black",
                      font=font)
        draw.line([(column * size, 0), (column * size, sheet.height)], fill=(180, 180, 180))
    sheet.save(out_png)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--out", required=True)
    parser.add_argument("--up", default="y", choices=["y", "z"], help="the meshes' up axis")
    parser.add_argument("--size", type=int, default=320, help="pixels per picture side")
    parser.add_argument("--second-view", action="store_true", help="add a row seen from the opposite side")
    parser.add_argument("meshes", nargs="+", help="OFF[:LABELS][=CAPTION]")
    args = parser.parse_args()
    items = []
    for spec in args.meshes:
        spec, _, caption = spec.partition("=")
        path, _, labels = spec.partition(":")
        items.append((path, labels or None, caption.replace("\\n", "\n") or path))
    panel(items, args.out, args.up, args.size, args.second_view)


if __name__ == "__main__":
    main()
