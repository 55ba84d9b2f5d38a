"""repair_many over 40 libcgal-demo meshes on a Dask LocalCluster of one, then two worker
processes (one thread each): wall time of each run and the speed-up. Cluster start-up is not
timed; each run writes into a fresh folder (no resuming).

    PYTHONPATH=build/python /usr/bin/python3 python/benchmarks/bench_batch.py \
        [MESH_FOLDER=.cache/cgal-demo/meshes | MESH_FILE] [FILES=40]

With a folder, the first FILES meshes of 100 kB to 3 MB by name (real files of very different
costs); with one mesh file, FILES copies of it (equal tasks: the scaling of the batch itself).
"""
import collections
import os
import shutil
import sys
import tempfile
import time

from distributed import Client, LocalCluster

from mesh_repair.batch import repair_many


def pick(folder, count):
    """The first `count` meshes of the folder by name between 100 kB and 3 MB: seconds each."""
    names = sorted(n for n in os.listdir(folder) if n.endswith((".off", ".obj", ".stl", ".ply")))
    sized = [n for n in names if 100e3 <= os.path.getsize(os.path.join(folder, n)) <= 3e6]
    return [os.path.join(folder, n) for n in sized[:count]]


def run(paths, workers, scratch):
    out_dir = os.path.join(scratch, f"out-{workers}")
    with LocalCluster(n_workers=workers, threads_per_worker=1, processes=True,
                      dashboard_address=None, local_directory=os.path.join(scratch, "dask")) \
            as cluster, Client(cluster) as client:
        start = time.perf_counter()
        rows = repair_many(paths, out_dir, client=client, timeout=600)
        seconds = time.perf_counter() - start
    outcomes = dict(collections.Counter(r["outcome"] for r in rows))
    print(f"{workers} worker(s): {seconds:.1f} s for {len(rows)} files, {outcomes}")
    return seconds, rows


def two_worker_bound(rows):
    """The best two workers can do with these per-file times (longest first, each to the less
    loaded worker): one long file can cap the speed-up below 2."""
    loads = [0.0, 0.0]
    for t in sorted((r["seconds"] for r in rows), reverse=True):
        loads[loads.index(min(loads))] += t
    return sum(loads) / max(loads)


def main():
    folder = sys.argv[1] if len(sys.argv) > 1 else ".cache/cgal-demo/meshes"
    count = int(sys.argv[2]) if len(sys.argv) > 2 else 40
    scratch = tempfile.mkdtemp(prefix="mesh_repair_bench_batch-")
    if os.path.isfile(folder):
        os.mkdir(os.path.join(scratch, "in"))
        name, extension = os.path.splitext(os.path.basename(folder))
        paths = [os.path.join(scratch, "in", f"{name}-{k:02d}{extension}") for k in range(count)]
        for path in paths:
            shutil.copyfile(folder, path)
    else:
        paths = pick(folder, count)
    print(f"{len(paths)} files from {folder}, "
          f"{sum(os.path.getsize(p) for p in paths) / 1e6:.1f} MB; load average "
          f"{os.getloadavg()[0]:.1f} on {os.cpu_count()} cores")
    try:
        one, rows = run(paths, 1, scratch)
        two, _ = run(paths, 2, scratch)
    finally:
        shutil.rmtree(scratch)
    longest = sorted(rows, key=lambda r: -r["seconds"])[:3]
    print("longest files (1 worker): " +
          ", ".join(f"{r['file']} {r['seconds']:.1f} s" for r in longest) +
          "; not repaired: " + ", ".join(f"{r['file']} ({r['outcome']}{': ' + r['note'] if r['note'] else ''})"
                                         for r in rows if r["outcome"] == "failed"))
    print(f"speed-up, 2 workers over 1: {one / two:.2f}x (at best {two_worker_bound(rows):.2f}x "
          f"for these per-file times); load average now {os.getloadavg()[0]:.1f}")


if __name__ == "__main__":
    main()
