#!/usr/bin/env python3
"""Held-out large, strongly non-planar holes for the hole-filling time bounds (issue 18).

  make_large_holes.py sphere LEVEL AMPLITUDE OUT.off
      an icosphere subdivided LEVEL times (20 * 4^LEVEL faces) without the faces above the
      wavy line z = AMPLITUDE * sin(6 theta): one hole, about half the sphere (level 6: 540
      border edges, level 7: 984).
  make_large_holes.py crown IN.off AMPLITUDE OFFSET OUT.off
      IN.off (an OFF of triangles) without the faces above the crown z = AMPLITUDE * sin(4 theta)
      + OFFSET, in coordinates centred on the mean vertex and scaled by half the largest extent:
      one or more holes whose borders wind up and down around the mesh.
"""
import math
import sys

from off_io import read_off, write_off


def normalized(p):
    n = math.sqrt(sum(c * c for c in p))
    return tuple(c / n for c in p)


def icosphere(level):
    t = (1 + 5 ** 0.5) / 2
    vertices = [normalized(v) for v in [(-1, t, 0), (1, t, 0), (-1, -t, 0), (1, -t, 0),
                                        (0, -1, t), (0, 1, t), (0, -1, -t), (0, 1, -t),
                                        (t, 0, -1), (t, 0, 1), (-t, 0, -1), (-t, 0, 1)]]
    faces = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4),
             (11, 10, 2), (10, 7, 6), (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8),
             (3, 8, 9), (4, 9, 5), (2, 4, 11), (6, 2, 10), (8, 6, 7), (9, 8, 1)]
    for _ in range(level):
        middle, refined = {}, []

        def mid(a, b):
            key = (min(a, b), max(a, b))
            if key not in middle:
                vertices.append(normalized([x + y for x, y in zip(vertices[a], vertices[b])]))
                middle[key] = len(vertices) - 1
            return middle[key]

        for a, b, c in faces:
            ab, bc, ca = mid(a, b), mid(b, c), mid(c, a)
            refined += [(a, ab, ca), (b, bc, ab), (c, ca, bc), (ab, bc, ca)]
        faces = refined
    return vertices, faces


def centroid(vertices, face):
    return [sum(vertices[v][k] for v in face) / len(face) for k in range(3)]


def main():
    if len(sys.argv) == 5 and sys.argv[1] == "sphere":
        vertices, faces = icosphere(int(sys.argv[2]))
        amplitude = float(sys.argv[3])
        above = lambda p: p[2] > amplitude * math.sin(6 * math.atan2(p[1], p[0]))
        out = sys.argv[4]
    elif len(sys.argv) == 6 and sys.argv[1] == "crown":
        vertices, faces = read_off(sys.argv[2])
        amplitude, offset, out = float(sys.argv[3]), float(sys.argv[4]), sys.argv[5]
        centre = [sum(v[k] for v in vertices) / len(vertices) for k in range(3)]
        half = max(max(v[k] for v in vertices) - min(v[k] for v in vertices) for k in range(3)) / 2
        scaled = [[(v[k] - centre[k]) / half for k in range(3)] for v in vertices]
        above = lambda p: p[2] > amplitude * math.sin(4 * math.atan2(p[1], p[0])) + offset
        kept = [f for f in faces if not above(centroid(scaled, f))]
        write_off(out, vertices, kept)
        return
    else:
        sys.exit(__doc__)
    write_off(out, vertices, [f for f in faces if not above(centroid(vertices, f))])


main()
