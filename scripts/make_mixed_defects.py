#!/usr/bin/env python3
"""Held-out dirty copies of closed (or open) triangle meshes, for checking `mesh_repair repair` on
defects of soups and CAD exports that no step was tuned on. Each copy gets four of seven defect
kinds, drawn per file, each applied to about one face in 400 (at least one):

  dup       a face repeated              dupflip   a face repeated in the opposite orientation
  flip      a face reversed              del       a face deleted (a small hole)
  seam      a face given its own copies of its three vertices (unshared seams)
  collapse  a vertex moved onto a neighbour (degenerate and folded fans)
  fold      a vertex moved by up to 1.5 median edge lengths along each axis

The faces are shuffled. Usage: make_mixed_defects.py SRC_DIR DST_DIR SEED NAME... (writes
DST_DIR/mx<SEED>_<NAME>, prints the kinds chosen per file; non-triangle faces are kept as they
are and not chosen)."""
import math
import os
import random
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from off_io import read_off, write_off  # noqa: E402

KINDS = ["dup", "dupflip", "flip", "del", "seam", "collapse", "fold"]


def median_edge(vertices, faces):
    lengths = sorted(math.dist(vertices[f[0]], vertices[f[1]]) for f in faces[:2000])
    return lengths[len(lengths) // 2] if lengths else 1.0


def make(src, dst, seed):
    rnd = random.Random(seed)
    vertices, faces = read_off(src)
    vertices = [list(v) for v in vertices]
    faces = [list(f) for f in faces]
    triangles = [i for i, f in enumerate(faces) if len(f) == 3]
    if not triangles:
        return None
    count = max(1, len(triangles) // 400)
    edge = median_edge(vertices, [faces[i] for i in triangles])
    kinds = rnd.sample(KINDS, 4)
    pick = lambda: faces[rnd.choice(triangles)]  # noqa: E731
    for kind in kinds:
        for _ in range(count):
            if kind == "del":
                i = rnd.randrange(len(faces))
                faces[i] = None
            elif kind == "flip":
                f = pick()
                f.reverse()
            elif kind == "dup":
                faces.append(list(pick()))
            elif kind == "dupflip":
                faces.append(pick()[::-1])
            elif kind == "collapse":
                f = pick()
                vertices[f[0]] = list(vertices[f[1]])
            elif kind == "fold":
                v = rnd.randrange(len(vertices))
                vertices[v] = [c + rnd.uniform(-1.5, 1.5) * edge for c in vertices[v]]
            elif kind == "seam":
                f = pick()
                for k, v in enumerate(f):
                    vertices.append(list(vertices[v]))
                    f[k] = len(vertices) - 1
        faces_left = [f for f in faces if f is not None]
        # keep `triangles` pointing at triangles of the current list
        faces = faces_left
        triangles = [i for i, f in enumerate(faces) if len(f) == 3]
    rnd.shuffle(faces)
    write_off(dst, vertices, faces)
    return kinds


def main():
    if len(sys.argv) < 5:
        raise SystemExit(__doc__)
    src_dir, dst_dir, seed = sys.argv[1], sys.argv[2], int(sys.argv[3])
    os.makedirs(dst_dir, exist_ok=True)
    for i, name in enumerate(sys.argv[4:]):
        dst = os.path.join(dst_dir, f"mx{seed}_{name}")
        kinds = make(os.path.join(src_dir, name), dst, seed * 100 + i)
        print(name, " ".join(kinds) if kinds else "skipped: no triangle")


if __name__ == "__main__":
    main()
