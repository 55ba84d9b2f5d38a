#!/usr/bin/env python3
"""Per-case comparison of `mesh_repair bench holes` results (results.jsonl files).

For each method: holes closed cleanly (closed, valid, no self-intersection), median Einf/diag
and E2/diag over its own clean holes, and the median per-case ratio of its error to CGAL's
continuity-1 fairing (liepa_c1) and to the better of CGAL's continuities 1 and 2 on that case.
"oracle" is the best of the four faired candidates of `self_validated` on each case: the bound a
per-hole choice among them could reach. Usage: compare_fills.py RESULTS.jsonl...
"""
import json
import statistics
import sys
from collections import defaultdict

CANDIDATES = ["shape_prediction", "liepa_c1", "curvature_variation", "liepa_c2"]


def load(paths):
    cases = defaultdict(dict)
    for path in paths:
        with open(path) as f:
            for line in f:
                r = json.loads(line)
                key = (r["mesh"], r["radius"], r["seed"], r["hole"], r.get("shape"))
                clean = r["closed"] and r["self_intersections"] == 0
                cases[key][r["method"]] = (r["einf_rel"], r["e2_rel"]) if clean else None
    return cases


def value(case, method, measure):
    if method == "oracle":
        values = [case[m][measure] for m in CANDIDATES if case.get(m)]
        return min(values) if values else None
    return case[method][measure] if case.get(method) else None


def main():
    cases = load(sys.argv[1:])
    methods = sorted({m for c in cases.values() for m in c})
    if all(m in methods for m in CANDIDATES):
        methods.append("oracle")
    print(f"{len(cases)} cases\n")
    print("| method | clean | median Einf/diag | median E2/diag | Einf / CGAL C1, per case "
          "(median) | Einf / best of CGAL C1, C2, per case (median) |")
    print("|---|---|---|---|---|---|")
    for m in methods:
        einf, e2, to_c1, to_best = [], [], [], []
        for c in cases.values():
            v = value(c, m, 0)
            if v is None:
                continue
            einf.append(v)
            e2.append(value(c, m, 1))
            refs = [c[r][0] for r in ("liepa_c1", "liepa_c2") if c.get(r)]
            if c.get("liepa_c1") and c["liepa_c1"][0] > 0:
                to_c1.append(v / c["liepa_c1"][0])
            if refs and min(refs) > 0:
                to_best.append(v / min(refs))
        if not einf:
            continue
        median = lambda xs: f"{statistics.median(xs):.3g}" if xs else "-"
        print(f"| {m} | {len(einf)} | {median(einf)} | {median(e2)} | {median(to_c1)} | "
              f"{median(to_best)} |")


if __name__ == "__main__":
    main()
