"""Repair every mesh of a folder on a Dask cluster; print the outcomes.

    # on this machine, a LocalCluster of two worker processes:
    PYTHONPATH=build/python /usr/bin/python3 examples/python/repair_many_dask.py IN_DIR OUT_DIR
    # on a running cluster (dask scheduler / dask worker, see doc/python.md):
    PYTHONPATH=build/python /usr/bin/python3 examples/python/repair_many_dask.py IN_DIR OUT_DIR \
        tcp://scheduler-host:8786
"""
import collections
import sys

from distributed import Client, LocalCluster

from mesh_repair.batch import repair_many

if __name__ == "__main__":  # LocalCluster starts processes: keep this guard
    in_dir, out_dir = sys.argv[1], sys.argv[2]
    if len(sys.argv) > 3:
        client = Client(sys.argv[3])
    else:
        client = Client(LocalCluster(n_workers=2, threads_per_worker=1, dashboard_address=None))
    with client:
        rows = repair_many(in_dir, out_dir, client=client, timeout=600)
    print(dict(collections.Counter(row["outcome"] for row in rows)))
    print(f"summary: {out_dir}/summary.csv, {out_dir}/summary.jsonl")
