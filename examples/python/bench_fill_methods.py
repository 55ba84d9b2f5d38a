"""The hole-filling benchmark on one closed mesh: punch holes, fill them with several methods,
and print each method's median error against the removed surface.

    PYTHONPATH=build/python /usr/bin/python3 examples/python/bench_fill_methods.py \
        [.cache/cgal-demo/meshes/elephant.off]
"""
import statistics
import sys

import mesh_repair

path = sys.argv[1] if len(sys.argv) > 1 else ".cache/cgal-demo/meshes/elephant.off"
report = mesh_repair.bench_holes(path, holes=4, radius=[0.04, 0.08], seeds=[1, 2],
                                 methods=["liepa_c1", "advancing_front", "self_validated"])
for shortfall in report["shortfalls"]:
    print(f"radius {shortfall['radius']}, seed {shortfall['seed']}: {shortfall['reason']}")
print(f"{report['input']}: {len(report['results'])} fills")
print(f"{'method':<18}{'closed':>8}{'Einf/diag':>11}{'E2/diag':>10}{'normal dev.':>13}")
for method in report["methods"]:
    rows = [r for r in report["results"] if r["method"] == method]
    closed = [r for r in rows if r["closed"]]

    def median(key):
        values = [r[key] for r in closed if r[key] is not None]
        return statistics.median(values) if values else float("nan")

    print(f"{method:<18}{len(closed):>4}/{len(rows):<3}{median('einf_rel'):>11.2e}"
          f"{median('e2_rel'):>10.2e}{median('normal_deviation_max_deg'):>12.1f}°")
