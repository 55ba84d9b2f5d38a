#!/usr/bin/env python3
"""Open meshes whose outline is long and jagged, for checking how `mesh_repair repair` closes
the outlines of scans that lost a whole side, on inputs no step was tuned on:

- cut/<name>_cut.off: a closed libcgal-demo mesh cut by a random plane 10-25 % up its extent
  along a random direction (every face with a corner below the plane removed), the vertices of
  the cut moved along that direction by up to half the mean edge length (a scan's jagged,
  sometimes folded border);
- terrain/terrain<NN>.off: a height field over [-1, 1]^2 (30-70 cells a side, a sum of four
  random waves up to 0.06 high) with 1-3 flat-topped blocks 0.2-0.8 high, its outline raised by
  0.05 and jittered by up to 0.02 (a building reconstructed on its patch of terrain: the ground
  lies on both sides of the outline's plane).

Usage: make_open_outlines.py MESH_DIR DST_DIR SEED
   (MESH_DIR: libcgal-demo's meshes, e.g. .cache/cgal-demo/meshes)"""
import math
import os
import random
import sys

CUT_MESHES = ("armadillo bear bull camel cow diplodocus dino elk homer lion man pig triceratops "
              "mushroom hand").split()


def read_off(path):
    rows = [line.split("#")[0].split() for line in open(path)]
    rows = [r for r in rows if r]
    head, k = (rows[0][1:], 1) if len(rows[0]) > 1 else (rows[1], 2)
    nv, nf = int(head[0]), int(head[1])
    points = [tuple(float(x) for x in rows[k + i][:3]) for i in range(nv)]
    faces = []
    for r in rows[k + nv:k + nv + nf]:
        if int(r[0]) == 3:
            faces.append(tuple(int(x) for x in r[1:4]))
    return points, faces


def write_off(path, points, faces):
    with open(path, "w") as out:
        out.write("OFF\n%d %d 0\n" % (len(points), len(faces)))
        for p in points:
            out.write("%.9g %.9g %.9g\n" % p)
        for f in faces:
            out.write("3 %d %d %d\n" % f)


def cut(points, faces, rng):
    d = [rng.gauss(0, 1) for _ in range(3)]
    n = math.sqrt(sum(x * x for x in d))
    d = [x / n for x in d]
    height = [sum(p[i] * d[i] for i in range(3)) for p in points]
    low, high = min(height), max(height)
    level = low + rng.uniform(0.1, 0.25) * (high - low)
    kept = [f for f in faces if all(height[v] > level for v in f)]
    used = sorted({v for f in kept for v in f})
    index = {v: i for i, v in enumerate(used)}
    pts = [list(points[v]) for v in used]
    tri = [tuple(index[v] for v in f) for f in kept]
    edges = {(f[i], f[(i + 1) % 3]) for f in tri for i in range(3)}
    border = {v for (a, b) in edges if (b, a) not in edges for v in (a, b)}
    lengths = [math.dist(pts[a], pts[b]) for (a, b) in edges]
    mean = sum(lengths) / max(1, len(lengths))
    for v in sorted(border):
        t = rng.uniform(-0.5, 0.5) * mean
        pts[v] = [pts[v][i] + t * d[i] for i in range(3)]
    return [tuple(p) for p in pts], tri


def terrain(rng):
    n = rng.randint(30, 70)
    waves = [(rng.uniform(1, 6), rng.uniform(1, 6), rng.uniform(0.01, 0.06), rng.uniform(0, 6))
             for _ in range(4)]
    blocks = [(rng.uniform(-0.5, 0.5), rng.uniform(-0.5, 0.5), rng.uniform(0.15, 0.4),
               rng.uniform(0.15, 0.4), rng.uniform(0.2, 0.8)) for _ in range(rng.randint(1, 3))]
    points = []
    for i in range(n + 1):
        for j in range(n + 1):
            x, y = -1 + 2 * i / n, -1 + 2 * j / n
            z = sum(c * math.sin(a * x + p) * math.cos(b * y + p) for a, b, c, p in waves)
            for cx, cy, w, l, h in blocks:
                if abs(x - cx) < w and abs(y - cy) < l:
                    z = h
            if i in (0, n) or j in (0, n):
                z += 0.05 + rng.uniform(-0.02, 0.02)
            points.append((x, y, z))
    faces = []
    for i in range(n):
        for j in range(n):
            a, b, c, d = i * (n + 1) + j, (i + 1) * (n + 1) + j, (i + 1) * (n + 1) + j + 1, \
                i * (n + 1) + j + 1
            faces += [(a, b, c), (a, c, d)]
    return points, faces


def main():
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    meshes, dst, seed = sys.argv[1], sys.argv[2], int(sys.argv[3])
    rng = random.Random(seed)
    os.makedirs(os.path.join(dst, "cut"), exist_ok=True)
    os.makedirs(os.path.join(dst, "terrain"), exist_ok=True)
    for name in CUT_MESHES:
        path = os.path.join(meshes, name + ".off")
        if os.path.exists(path):
            write_off(os.path.join(dst, "cut", name + "_cut.off"), *cut(*read_off(path), rng))
    for k in range(12):
        write_off(os.path.join(dst, "terrain", "terrain%02d.off" % k), *terrain(rng))


if __name__ == "__main__":
    main()
