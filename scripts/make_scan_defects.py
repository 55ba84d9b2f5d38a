"""Scan-like defects on a closed mesh, for held-out repair benchmarks: spikes (a share of the
vertices moved by 1-3 mean edge lengths in random directions: folds and self-intersections),
jagged holes (random face regions grown from seeds, which leave fragments of a face or a few in
the hole, attached at a vertex or floating), 0.5% of the faces reversed and 3 faces duplicated.
Usage: make_scan_defects.py IN.off OUT.off SEED [SPIKE_SHARE=0.01] [MAX_HOLE_FACES=60]"""
import math
import os
import random
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from off_io import read_off, write_off  # noqa: E402


def main():
    source, target, seed = sys.argv[1], sys.argv[2], int(sys.argv[3])
    spike_share = float(sys.argv[4]) if len(sys.argv) > 4 else 0.01
    max_hole_faces = int(sys.argv[5]) if len(sys.argv) > 5 else 60
    rng = random.Random(seed)
    vertices, polygons = read_off(source)
    vertices = [list(p) for p in vertices]
    faces = [list(f) for f in polygons if len(f) == 3]
    sample = faces[:2000]
    edge = sum(math.dist(vertices[f[0]], vertices[f[1]]) for f in sample) / len(sample)
    around = {}
    for i, f in enumerate(faces):
        for v in f:
            around.setdefault(v, []).append(i)
    for v in rng.sample(range(len(vertices)), max(3, int(spike_share * len(vertices)))):
        d = [rng.gauss(0, 1) for _ in range(3)]
        n = math.sqrt(sum(x * x for x in d)) or 1
        s = edge * rng.uniform(1, 3)
        vertices[v] = [vertices[v][k] + d[k] / n * s for k in range(3)]
    removed = set()
    for _ in range(rng.randint(3, 10)):
        start = rng.randrange(len(faces))
        region, front = {start}, [start]
        size = rng.randint(5, max_hole_faces)
        while front and len(region) < size:
            f = front.pop(rng.randrange(len(front)))
            for v in faces[f]:
                for g in around[v]:
                    if g not in region and rng.random() < 0.5:
                        region.add(g)
                        front.append(g)
        removed |= region
    kept = [f for i, f in enumerate(faces) if i not in removed]
    for i in rng.sample(range(len(kept)), len(kept) // 200):
        kept[i] = kept[i][::-1]
    kept += [list(kept[i]) for i in rng.sample(range(len(kept)), min(3, len(kept)))]
    write_off(target, vertices, kept)


if __name__ == "__main__":
    main()
