#!/usr/bin/env python3
"""Writes data/demo/defective_part.off: a CAD-like block exported the way broken exporters do.

The block [0,4]x[0,2]x[0,1] is meshed face by face (each face a separate grid, as a CAD exporter
writes patches), which gives:
  - duplicated vertices along every patch seam (merged by the soup stage),
  - a gap: the top patch is lifted by 0.004 and shrunk, so its border does not meet the sides,
  - T-junctions: the front patch has twice the resolution of its neighbours along x,
  - a hole: a disc of faces removed from the top patch (a "removed feature"),
  - a flipped triangle, a duplicated triangle and a zero-area (collinear) triangle.
Deterministic: no randomness.
"""
import math
import os

points, faces = [], []


def grid(origin, du, dv, nu, nv, skip=lambda i, j: False):
    base = len(points)
    for j in range(nv + 1):
        for i in range(nu + 1):
            points.append([origin[k] + du[k] * i / nu + dv[k] * j / nv for k in range(3)])
    for j in range(nv):
        for i in range(nu):
            if skip(i, j):
                continue
            a = base + j * (nu + 1) + i
            b, c, d = a + 1, a + nu + 2, a + nu + 1
            faces.append([a, b, c])
            faces.append([a, c, d])


L, W, H = 4.0, 2.0, 1.0
grid([0, 0, 0], [0, W, 0], [L, 0, 0], 8, 16)            # bottom (normal -z)
grid([0, 0, 0], [L, 0, 0], [0, 0, H], 32, 4)            # front y=0, finer: T-junctions
grid([0, W, 0], [0, 0, H], [L, 0, 0], 4, 16)            # back y=W
grid([0, 0, 0], [0, 0, H], [0, W, 0], 4, 8)             # left x=0
grid([L, 0, 0], [0, W, 0], [0, 0, H], 8, 4)             # right x=L

# top: lifted by a small gap and with a round hole (the removed feature)
lift = 0.004


def in_hole(i, j, nu=16, nv=8):
    cx, cy = (i + 0.5) / nu * L, (j + 0.5) / nv * W
    return (cx - 2.6) ** 2 + (cy - 1.0) ** 2 < 0.45 ** 2


grid([0, 0, H + lift], [L, 0, 0], [0, W, 0], 16, 8, skip=in_hole)

faces[10] = [faces[10][0], faces[10][2], faces[10][1]]   # a flipped triangle
faces.append(list(faces[20]))                            # a duplicated triangle
p = len(points)
points += [[1.0, 0.5, -0.02], [1.2, 0.5, -0.02], [1.4, 0.5, -0.02]]
faces.append([p, p + 1, p + 2])                          # a zero-area triangle, detached

here = os.path.dirname(os.path.abspath(__file__))
out = os.path.join(here, "..", "data", "demo", "defective_part.off")
with open(out, "w") as f:
    f.write("OFF\n# Mesh_repair demo: a CAD block with gaps, T-junctions, a hole and bad faces\n")
    f.write(f"{len(points)} {len(faces)} 0\n")
    for q in points:
        f.write(" ".join(f"{c:.6f}" for c in q) + "\n")
    for t in faces:
        f.write("3 " + " ".join(map(str, t)) + "\n")
print(f"wrote {out}: {len(points)} points, {len(faces)} triangles")
