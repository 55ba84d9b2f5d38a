#!/usr/bin/env python3
"""Cracked copies of a closed triangle mesh, for the stitching benchmarks (issue 20).

The mesh is cut across by a plane of random direction (faces go by their centroid, so the cut runs
along existing edges), the upper half gets its own copies of the cut vertices, every K-th edge of
its cut border is split at 0.4 (with its triangle) so the nodes of the two sides stop matching
(T-junctions), and the upper half is moved away along the plane's normal by GAP x the bounding-box
diagonal. The result is a mesh with one crack whose sides are GAP apart with non-matching nodes.

Usage: make_cracked_meshes.py IN.off OUT.off GAP SEED [K]   (K: default 3)
"""
import math
import random
import sys

from off_io import read_off, write_off


def pieces(faces, upper, side):
    """Connected pieces (edge-adjacent) of the faces with upper[i] == side, largest first."""
    by_edge = {}
    for i, f in enumerate(faces):
        if upper[i] == side:
            for a, b in ((f[0], f[1]), (f[1], f[2]), (f[2], f[0])):
                by_edge.setdefault((min(a, b), max(a, b)), []).append(i)
    seen, found = set(), []
    for start in range(len(faces)):
        if upper[start] != side or start in seen:
            continue
        piece, stack = [], [start]
        seen.add(start)
        while stack:
            i = stack.pop()
            piece.append(i)
            f = faces[i]
            for a, b in ((f[0], f[1]), (f[1], f[2]), (f[2], f[0])):
                for j in by_edge[(min(a, b), max(a, b))]:
                    if j not in seen:
                        seen.add(j)
                        stack.append(j)
        found.append(piece)
    return sorted(found, key=len, reverse=True)


def main():
    src, out, gap, seed = sys.argv[1], sys.argv[2], float(sys.argv[3]), int(sys.argv[4])
    every = int(sys.argv[5]) if len(sys.argv) > 5 else 3
    vertices, faces = read_off(src)
    if any(len(f) != 3 for f in faces):
        raise SystemExit(f"{src}: triangles only")
    rng = random.Random(seed)
    normal = [rng.gauss(0, 1) for _ in range(3)]
    length = math.sqrt(sum(c * c for c in normal))
    normal = [c / length for c in normal]
    lo = [min(v[k] for v in vertices) for k in range(3)]
    hi = [max(v[k] for v in vertices) for k in range(3)]
    diagonal = math.dist(lo, hi)
    height = [sum(normal[k] * sum(vertices[i][k] for i in f) / 3 for k in range(3)) for f in faces]
    cut = sorted(height)[int(len(height) * rng.uniform(0.35, 0.65))]
    upper = [h >= cut for h in height]
    # Faces cut off from their side (a face above among faces below) go to the other side: each
    # side is one connected piece, so the crack is a clean cut and adds no small sheets.
    for side in (True, False):
        for piece in pieces(faces, upper, side)[1:]:
            for i in piece:
                upper[i] = not side
    upper_faces = [i for i in range(len(faces)) if upper[i]]
    lower_vertices = {v for i in range(len(faces)) if not upper[i] for v in faces[i]}
    # The upper half's own copies of the cut vertices.
    copy = {}
    for i in upper_faces:
        for k, v in enumerate(faces[i]):
            if v in lower_vertices:
                if v not in copy:
                    copy[v] = len(vertices)
                    vertices.append(list(vertices[v]))
                faces[i][k] = copy[v]
    # Border edges of the upper half (edges used once among its faces) on the cut.
    uses = {}
    for i in upper_faces:
        f = faces[i]
        for a, b in ((f[0], f[1]), (f[1], f[2]), (f[2], f[0])):
            uses[(min(a, b), max(a, b))] = uses.get((min(a, b), max(a, b)), 0) + 1
    cut_edges = []
    for i in upper_faces:
        f = faces[i]
        for j in range(3):
            a, b = f[j], f[(j + 1) % 3]
            if uses[(min(a, b), max(a, b))] == 1 and a in copy.values() and b in copy.values():
                cut_edges.append((i, j))
    cut_edges.sort()
    moved = {v for i in upper_faces for v in faces[i]}
    for n, (i, j) in enumerate(cut_edges):
        if n % every:
            continue
        f = faces[i]
        a, b, c = f[j], f[(j + 1) % 3], f[(j + 2) % 3]
        m = len(vertices)
        vertices.append([vertices[a][k] + 0.4 * (vertices[b][k] - vertices[a][k]) for k in range(3)])
        moved.add(m)
        faces[i] = [a, m, c]
        faces.append([m, b, c])
    shift = gap * diagonal
    for v in moved:
        vertices[v] = [vertices[v][k] + shift * normal[k] for k in range(3)]
    write_off(out, vertices, faces)
    print(f"{out}: cut of {len(cut_edges)} edges, {len(cut_edges[::every])} split, "
          f"gap {shift:.6g} ({gap} x diagonal {diagonal:.6g})")


if __name__ == "__main__":
    main()
