"""Reading OFF meshes, standard library only: the bench scripts' one reader."""


def read_off(path):
    """Vertices as (x, y, z) tuples and faces as lists of vertex indices. Comments are skipped;
    the counts may follow "OFF" on its line; values after a face's indices (vsa-bench's colours)
    are ignored."""
    with open(path) as f:
        lines = [line.split("#", 1)[0].split() for line in f]
    lines = [t for t in lines if t]
    if not lines or not lines[0][0].endswith("OFF"):
        raise SystemExit("%s: not an OFF file" % path)
    header = lines[0]
    counts = header[1:] if len(header) > 1 else lines[1]
    start = 1 if len(header) > 1 else 2
    vertex_count, face_count = int(counts[0]), int(counts[1])
    vertices = [tuple(float(x) for x in t[:3]) for t in lines[start:start + vertex_count]]
    faces = [[int(x) for x in t[1:1 + int(t[0])]] for t in lines[start + vertex_count:start + vertex_count + face_count]]
    return vertices, faces
