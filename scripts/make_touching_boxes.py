#!/usr/bin/env python3
"""Assemblies of closed boxes that touch one another face to face, edge to edge and corner to
corner, for checking `mesh_repair repair` on contacts between parts that no step was tuned on:
each file holds 2 to 6 unit cells of a 4 x 4 x 3 grid (distinct cells, drawn at random), each cell a
closed outward box with points of its own, scaled by 1, 0.37 or 123.4 (drawn per file).

Usage: make_touching_boxes.py DST_DIR COUNT SEED   (writes DST_DIR/b<NN>.off)"""
import os
import random
import sys

FACES = [(0, 2, 1), (1, 2, 3), (4, 5, 6), (5, 7, 6), (0, 1, 4), (1, 5, 4),
         (2, 6, 3), (3, 6, 7), (0, 4, 2), (2, 4, 6), (1, 3, 5), (3, 7, 5)]


def assembly(rng):
    cells = {(rng.randint(0, 3), rng.randint(0, 3), rng.randint(0, 2))
             for _ in range(rng.randint(2, 6))}
    scale = rng.choice([1.0, 0.37, 123.4])
    points, triangles = [], []
    for c in sorted(cells):
        first = len(points)
        points += [((c[0] + (i & 1)) * scale, (c[1] + ((i >> 1) & 1)) * scale,
                    (c[2] + ((i >> 2) & 1)) * scale) for i in range(8)]
        triangles += [tuple(first + v for v in f) for f in FACES]
    return points, triangles


def main():
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    out, count, rng = sys.argv[1], int(sys.argv[2]), random.Random(int(sys.argv[3]))
    os.makedirs(out, exist_ok=True)
    written = 0
    while written < count:
        points, triangles = assembly(rng)
        if len(triangles) < 24:  # one cell drawn twice or more: no contact
            continue
        with open(os.path.join(out, "b%02d.off" % written), "w") as f:
            f.write("OFF\n%d %d 0\n" % (len(points), len(triangles)))
            f.writelines("%.17g %.17g %.17g\n" % p for p in points)
            f.writelines("3 %d %d %d\n" % t for t in triangles)
        written += 1


if __name__ == "__main__":
    main()
