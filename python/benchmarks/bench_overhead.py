"""Python overhead of mesh_repair.repair over the C++ work it wraps, on the mesh of
Mesh_repair/benchmark/bench_repair.cpp: an icosphere of 1,310,720 faces jittered like a scan with
100 disc holes (faces with a corner within 0.06 of a Fibonacci-lattice centre removed; the
unused vertices stay and the soup stage removes them).

The report's `seconds` is measured inside the C++ operator (soup stage on the copied arrays,
defects before, automatic_repair, defects after: what `mesh_repair repair` does between reading
and writing). The overhead is the rest of the Python call: checking and copying the arrays in,
the arrays and the JSON report out.

    PYTHONPATH=build/python /usr/bin/python3 python/benchmarks/bench_overhead.py [runs=3] [subdivisions=8]
"""
import statistics
import sys
import time

import numpy as np

import mesh_repair


def icosphere(subdivisions):
    t = (1 + 5 ** 0.5) / 2
    v = np.array([[-1, t, 0], [1, t, 0], [-1, -t, 0], [1, -t, 0], [0, -1, t], [0, 1, t],
                  [0, -1, -t], [0, 1, -t], [t, 0, -1], [t, 0, 1], [-t, 0, -1], [-t, 0, 1]], float)
    f = np.array([[0, 11, 5], [0, 5, 1], [0, 1, 7], [0, 7, 10], [0, 10, 11], [1, 5, 9],
                  [5, 11, 4], [11, 10, 2], [10, 7, 6], [7, 1, 8], [3, 9, 4], [3, 4, 2],
                  [3, 2, 6], [3, 6, 8], [3, 8, 9], [4, 9, 5], [2, 4, 11], [6, 2, 10], [8, 6, 7],
                  [9, 8, 1]])
    v /= np.linalg.norm(v, axis=1)[:, None]
    for _ in range(subdivisions):
        edges = np.sort(np.vstack([f[:, [0, 1]], f[:, [1, 2]], f[:, [2, 0]]]), axis=1)
        unique, index = np.unique(edges, axis=0, return_inverse=True)
        middle = v[unique].mean(axis=1)
        first_new = len(v)
        v = np.vstack([v, middle / np.linalg.norm(middle, axis=1)[:, None]])
        m = len(f)
        ab, bc, ca = (index[k * m:(k + 1) * m] + first_new for k in range(3))
        a, b, c = f.T
        f = np.vstack([np.c_[a, ab, ca], np.c_[b, bc, ab], np.c_[c, ca, bc], np.c_[ab, bc, ca]])
    return v, f


def scan_with_holes(subdivisions, holes=100, radius=0.06):
    v, f = icosphere(subdivisions)
    v = v * (1.0 + np.random.default_rng(7).normal(0.0, 1e-4, size=(len(v), 1)))
    i = np.arange(holes)
    z = 1.0 - 2.0 * (i + 0.5) / holes
    phi = i * np.pi * (3.0 - np.sqrt(5.0))
    centres = np.c_[np.sqrt(1 - z * z) * np.cos(phi), np.sqrt(1 - z * z) * np.sin(phi), z]
    # A face goes when any corner is in a disc, so no vertex is left pinched between two holes
    # (the soup stage would split it, and the fill would see two touching holes).
    near = np.zeros(len(v), bool)
    for c in centres:
        near |= np.einsum("ij,ij->i", v - c, v - c) < radius * radius
    return v, f[~near[f].any(axis=1)]


def main():
    runs = int(sys.argv[1]) if len(sys.argv) > 1 else 3
    subdivisions = int(sys.argv[2]) if len(sys.argv) > 2 else 8
    vertices, faces = scan_with_holes(subdivisions)
    print(f"input: {len(faces)} faces, {len(vertices)} vertices")
    overheads = []
    for run in range(runs):
        start = time.perf_counter()
        result = mesh_repair.repair(vertices, faces, threads=1)
        wall = time.perf_counter() - start
        inner = result.report["seconds"]
        overheads.append((wall - inner) / inner)
        repair = result.report["repair"]
        print(f"run {run + 1}: Python call {wall:.3f} s, C++ work {inner:.3f} s, overhead "
              f"{wall - inner:.3f} s = {100 * overheads[-1]:.2f}% ({repair['holes_filled']} "
              f"holes filled, closed={repair['closed']}, {len(result.faces)} faces out)")
    print(f"median overhead: {100 * statistics.median(overheads):.2f}%")


if __name__ == "__main__":
    main()
