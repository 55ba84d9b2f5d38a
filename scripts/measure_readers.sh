#!/bin/sh
# Peak memory and time of our readers alone (no soup repair) on large generated files, the
# figures of doc/fuzzing.md. Writes the files into a temporary folder (about 1.5 GB with the
# sparse ones taking no space) and removes it. Usage: scripts/measure_readers.sh [MB per file]
set -eu
ROOT=$(cd "$(dirname "$0")/.." && pwd)
MB=${1:-100}
DIR=$(mktemp -d)
trap 'rm -rf "$DIR"' EXIT
g++ -std=c++17 -O2 -DNDEBUG -I"$ROOT/Mesh_repair/include" "$ROOT/test/fuzz/read_soup_stats.cpp" \
  -o "$DIR/read_soup_stats" -lgmp -lmpfr
python3 - "$DIR" "$MB" <<'PY'
import os, struct, sys
d, mb = sys.argv[1], int(sys.argv[2])
target = mb * 1000000
def grid(n):  # n x n points, 2 (n-1)^2 triangles
    pts = [(i, j, (i * j) % 7) for i in range(n) for j in range(n)]
    tris = []
    for i in range(n - 1):
        for j in range(n - 1):
            a, b, c, e = i * n + j, i * n + j + 1, (i + 1) * n + j, (i + 1) * n + j + 1
            tris += [(a, b, e), (a, e, c)]
    return pts, tris
# ASCII OFF: sized by the grid; roughly 40 bytes per point and triangle pair
n = int((target / 48) ** 0.5)
pts, tris = grid(n)
with open(os.path.join(d, "grid.off"), "w") as f:
    f.write("OFF\n%d %d 0\n" % (len(pts), len(tris)))
    f.writelines("%d %d %d\n" % p for p in pts)
    f.writelines("3 %d %d %d\n" % t for t in tris)
with open(os.path.join(d, "grid.obj"), "w") as f:
    f.writelines("v %d %d %d\n" % p for p in pts)
    f.writelines("f %d %d %d\n" % (t[0] + 1, t[1] + 1, t[2] + 1) for t in tris)
# Worst case of ASCII OFF: the shortest triangle records, "3 0 1 2"
k = target // 8
with open(os.path.join(d, "short_faces.off"), "w") as f:
    f.write("OFF\n3 %d 0\n0 0 0\n1 0 0\n0 1 0\n" % k)
    f.write("3 0 1 2\n" * k)
# Worst case of binary PLY: uchar indices, 4 bytes per triangle
k = target // 4
with open(os.path.join(d, "uchar_faces.ply"), "wb") as f:
    f.write(b"ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\n"
            b"property float y\nproperty float z\nelement face %d\n"
            b"property list uchar uchar vertex_indices\nend_header\n" % k)
    f.write(struct.pack("<9f", 0, 0, 0, 1, 0, 0, 0, 1, 0))
    f.write(b"\x03\x00\x01\x02" * k)
# Binary STL of distinct triangles (point merging at its most expensive)
k = target // 50
with open(os.path.join(d, "distinct.stl"), "wb") as f:
    f.write(b"\0" * 80 + struct.pack("<I", k))
    rec = bytearray()
    for t in range(k):
        x = float(t)
        rec += struct.pack("<12fH", 0, 0, 1, x, 0, 0, x + 0.5, 1, 0, x, 0, 1, 0)
        if len(rec) > 1 << 20:
            f.write(rec); rec = bytearray()
    f.write(rec)
PY
# Sparse 2 GB files: headers that fit the size, then zeros.
printf 'OFF\n100000000 100000000 0\n' >"$DIR/sparse.off"
printf 'v 0 0 0\n' >"$DIR/sparse.obj"
printf 'solid x\n' >"$DIR/sparse.stl"
printf 'ply\nformat binary_little_endian 1.0\nelement vertex 100000000\nproperty float x\nproperty float y\nproperty float z\nelement face 100000000\nproperty list uchar int vertex_indices\nend_header\n' >"$DIR/sparse.ply"
for f in sparse.off sparse.obj sparse.stl sparse.ply; do truncate -s 2G "$DIR/$f"; done
for f in grid.off grid.obj short_faces.off uchar_faces.ply distinct.stl sparse.off sparse.obj sparse.stl sparse.ply; do
  /usr/bin/time -f "  peak %M KB, %e s wall, %U s user" "$DIR/read_soup_stats" "$DIR/$f" 2>&1 | sed "s|$DIR/||" || true
done
