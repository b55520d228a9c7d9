#!/usr/bin/env python3
"""Writes sample_holes.ply: a bumpy closed blob with three holes of different sizes, the
product's own sample mesh (the scans in ../shared are not ours to ship)."""
import math
import struct
import sys


def icosphere(subdiv):
    t = (1 + 5 ** 0.5) / 2
    verts = [(-1, t, 0), (1, t, 0), (-1, -t, 0), (1, -t, 0), (0, -1, t), (0, 1, t),
             (0, -1, -t), (0, 1, -t), (t, 0, -1), (t, 0, 1), (-t, 0, -1), (-t, 0, 1)]
    verts = [tuple(c / math.sqrt(sum(x * x for x in v)) for c in v) for v in verts]
    faces = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4),
             (11, 10, 2), (10, 7, 6), (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8),
             (3, 8, 9), (4, 9, 5), (2, 4, 11), (6, 2, 10), (8, 6, 7), (9, 8, 1)]
    for _ in range(subdiv):
        cache, out = {}, []

        def mid(a, b):
            key = (min(a, b), max(a, b))
            if key not in cache:
                p = [(x + y) / 2 for x, y in zip(verts[a], verts[b])]
                n = math.sqrt(sum(c * c for c in p))
                verts.append(tuple(c / n for c in p))
                cache[key] = len(verts) - 1
            return cache[key]

        for a, b, c in faces:
            ab, bc, ca = mid(a, b), mid(b, c), mid(c, a)
            out += [(a, ab, ca), (b, bc, ab), (c, ca, bc), (ab, bc, ca)]
        faces = out
    return verts, faces


def main(path):
    verts, faces = icosphere(5)
    # Bumps of several scales, so a fill has curvature to continue.
    def radius(x, y, z):
        return 1 + 0.12 * math.sin(4 * x) * math.sin(4 * y) * math.sin(4 * z) + 0.05 * math.cos(9 * x + 3 * z)
    verts = [tuple(c * radius(*v) for c in v) for v in verts]
    holes = [((0.9, 0.3, 0.3), 0.22), ((-0.2, 0.95, -0.1), 0.14), ((0.1, -0.3, -0.95), 0.32)]
    def inside(p):
        return any(sum((a - b) ** 2 for a, b in zip(p, c)) < r * r for c, r in holes)
    faces = [f for f in faces if not any(inside(verts[i]) for i in f)]
    used = sorted({i for f in faces for i in f})
    index = {old: new for new, old in enumerate(used)}
    with open(path, "wb") as out:
        out.write(b"ply\nformat binary_little_endian 1.0\ncomment curvature-inpaint sample: bumpy blob, 3 holes\n")
        out.write(f"element vertex {len(used)}\nproperty float x\nproperty float y\nproperty float z\n".encode())
        out.write(f"element face {len(faces)}\nproperty list uchar int vertex_indices\nend_header\n".encode())
        for i in used:
            out.write(struct.pack("<3f", *verts[i]))
        for f in faces:
            out.write(struct.pack("<B3i", 3, *(index[i] for i in f)))


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "sample_holes.ply")
