#!/usr/bin/env python3
"""Defective meshes of a chosen size, for checking that `repair` grows in proportion to its input
(scripts/bench_scaling.sh runs each kind at N and 4N parts).

Usage: make_scaling_inputs.py KIND N OUT.off
KIND:
  separate_faces       N triangles of unit size scattered in a cube of side 100 (a soup of
                       separate faces: every border an island cycle)
  intersecting_spheres N closed spheres of 80 faces, each overlapping its neighbours (for
                       --merge-intersecting-solids)
  small_holes          a wavy sheet with N one-quad holes
  separate_cubes       N closed cubes apart
  duplicated_faces     a closed sphere of about 2N faces with every fifth face twice
  overlapping_sheets   two grid sheets of about N faces each, one shifted by a third of a cell
                       in their plane
"""
import math
import random
import sys

from off_io import write_off


def sphere(vertices, faces, centre, radius, nu=8, nv=6, turn=0.0):
    base = len(vertices)
    cx, cy, cz = centre
    vertices.append([cx, cy, cz + radius])
    for i in range(1, nv):
        t = math.pi * i / nv
        for j in range(nu):
            p = 2 * math.pi * j / nu + turn
            vertices.append([cx + radius * math.sin(t) * math.cos(p),
                             cy + radius * math.sin(t) * math.sin(p), cz + radius * math.cos(t)])
    vertices.append([cx, cy, cz - radius])
    south = len(vertices) - 1

    def ring(i, j):
        return base + 1 + (i - 1) * nu + j % nu
    for j in range(nu):
        faces.append([base, ring(1, j), ring(1, j + 1)])
        faces.append([south, ring(nv - 1, j + 1), ring(nv - 1, j)])
    for i in range(1, nv - 1):
        for j in range(nu):
            faces.append([ring(i, j), ring(i + 1, j), ring(i + 1, j + 1)])
            faces.append([ring(i, j), ring(i + 1, j + 1), ring(i, j + 1)])


def cube(vertices, faces, corner, size=1.0):
    base = len(vertices)
    for i in range(8):
        vertices.append([corner[0] + size * (i & 1), corner[1] + size * ((i >> 1) & 1),
                         corner[2] + size * ((i >> 2) & 1)])
    for q in [(0, 2, 3, 1), (4, 5, 7, 6), (0, 1, 5, 4), (2, 6, 7, 3), (0, 4, 6, 2), (1, 3, 7, 5)]:
        faces.append([base + q[0], base + q[1], base + q[2]])
        faces.append([base + q[0], base + q[2], base + q[3]])


def grid(vertices, faces, k, shift=0.0, skip=()):
    base = len(vertices)
    for i in range(k + 1):
        for j in range(k + 1):
            vertices.append([i + shift, j + shift, 0.0])
    for i in range(k):
        for j in range(k):
            if (i, j) in skip:
                continue
            a = base + i * (k + 1) + j
            faces.append([a, a + k + 1, a + k + 2])
            faces.append([a, a + k + 2, a + 1])


def main():
    if len(sys.argv) != 4:
        raise SystemExit(__doc__)
    kind, n, out = sys.argv[1], int(sys.argv[2]), sys.argv[3]
    random.seed(5)
    vertices, faces = [], []
    side = int(round(n ** (1 / 3))) + 1
    cell = [(i % side, (i // side) % side, i // (side * side)) for i in range(n)]
    if kind == "separate_faces":
        for _ in range(n):
            corner = [random.uniform(0, 100) for _ in range(3)]
            base = len(vertices)
            for _ in range(3):
                vertices.append([c + random.uniform(0, 1) for c in corner])
            faces.append([base, base + 1, base + 2])
    elif kind == "intersecting_spheres":
        for x, y, z in cell:
            sphere(vertices, faces, [1.3 * c + random.uniform(-0.1, 0.1) for c in (x, y, z)],
                   random.uniform(0.75, 0.85), turn=random.random())
    elif kind == "small_holes":
        k = 3 * int(math.sqrt(n))
        holes = {(3 * (h % (k // 3)) + 1, 3 * (h // (k // 3)) + 1) for h in range(n)}
        grid(vertices, faces, k, skip=holes)
        vertices = [[x, y, 0.3 * math.sin(0.7 * x) * math.cos(0.5 * y)] for x, y, _ in vertices]
    elif kind == "separate_cubes":
        for x, y, z in cell:
            cube(vertices, faces, [2 * x, 2 * y, 2 * z])
    elif kind == "duplicated_faces":
        k = int(math.sqrt(n))
        sphere(vertices, faces, [0, 0, 0], 1.0, nu=2 * k, nv=k)
        faces += faces[::5]
    elif kind == "overlapping_sheets":
        k = int(math.sqrt(n / 2))
        grid(vertices, faces, k)
        grid(vertices, faces, k, shift=0.33)
    else:
        raise SystemExit(__doc__)
    write_off(out, vertices, faces)
    print(f"{out}: {len(vertices)} vertices, {len(faces)} faces")


if __name__ == "__main__":
    main()
