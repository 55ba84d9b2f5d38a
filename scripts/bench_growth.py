#!/usr/bin/env python3
"""Time of each hole-filling method against a reference method, per hole, from the
results.jsonl of `mesh_repair bench holes` (doc/bench_holes.md, "Time and its growth").

For every method and every reference (default liepa_c1 and liepa_c2: CGAL's
triangulate_refine_and_fair_hole at continuity 1 and 2), over the holes both closed:
  - the median time of each and their ratio, and the median of the per-hole time ratios;
  - the median per-hole ratio by border-size class;
  - the growth with the border size: the least-squares slope of log(time) against
    log(border edges) for both methods, and the slope of log(time ratio) against
    log(border edges) with its standard error and 95% interval. The ratio grows with the border
    when that interval lies above 0.
A method that falls back to another (shape_prediction: advancing_front, then Liepa) is also
measured on the holes it filled itself ("own fill").

Only the standard library: usable on a fresh machine without numpy.
Usage: scripts/bench_growth.py RESULTS.jsonl [--reference liepa_c1,liepa_c2]   (a markdown table)
"""
import argparse
import json
import math
import statistics
import sys

CLASSES = [(0, 40), (40, 80), (80, 160), (160, None)]


def hole_key(row):
    return (row["mesh"], row["shape"], row["radius"], row["seed"], row["hole"])


def closed(row):
    return row["closed"] and row["self_intersections"] == 0 and row["seconds"] > 0


def fit_line(xs, ys):
    """Least-squares y = a + b x: (b, standard error of b)."""
    n = len(xs)
    if n < 3:
        return float("nan"), float("nan")
    mx, my = statistics.fmean(xs), statistics.fmean(ys)
    sxx = sum((x - mx) ** 2 for x in xs)
    if sxx == 0:
        return float("nan"), float("nan")
    b = sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sxx
    a = my - b * mx
    residual = sum((y - a - b * x) ** 2 for x, y in zip(xs, ys))
    return b, math.sqrt(residual / (n - 2) / sxx)


def class_name(lo, hi):
    return f"{lo}-{hi}" if hi is not None else f">{lo}"


def compare(pairs, label):
    """pairs: list of (border_edges, method seconds, reference seconds)."""
    if not pairs:
        return None
    edges = [p[0] for p in pairs]
    ratios = [p[1] / p[2] for p in pairs]
    lx = [math.log(e) for e in edges]
    slope_method, _ = fit_line(lx, [math.log(p[1]) for p in pairs])
    slope_reference, _ = fit_line(lx, [math.log(p[2]) for p in pairs])
    slope_ratio, error = fit_line(lx, [math.log(r) for r in ratios])
    by_class = []
    for lo, hi in CLASSES:
        inside = [r for e, r in zip(edges, ratios) if e >= lo and (hi is None or e < hi)]
        by_class.append((class_name(lo, hi), len(inside),
                         statistics.median(inside) if inside else float("nan")))
    method_median = statistics.median(p[1] for p in pairs)
    reference_median = statistics.median(p[2] for p in pairs)
    return {
        "label": label,
        "holes": len(pairs),
        "method_median": method_median,
        "reference_median": reference_median,
        "ratio_of_medians": method_median / reference_median,
        "median_ratio": statistics.median(ratios),
        "worst_ratio": max(ratios),
        "slope_method": slope_method,
        "slope_reference": slope_reference,
        "slope_ratio": slope_ratio,
        "slope_ratio_error": error,
        "by_class": by_class,
    }


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("results")
    parser.add_argument("--reference", default="liepa_c1,liepa_c2")
    args = parser.parse_args()

    rows = {}
    methods = []
    with open(args.results) as f:
        for line in f:
            line = line.strip()
            if not line:
                continue
            row = json.loads(line)
            if row["method"] not in methods:
                methods.append(row["method"])
            rows.setdefault(row["method"], {})[hole_key(row)] = row
    references = [r for r in args.reference.split(",") if r in rows]
    if not references:
        sys.exit(f"bench_growth: none of the reference methods {args.reference} in {args.results}")

    results = []
    for reference in references:
        for method in methods:
            if method in references:
                continue
            both = [(r["border_edges"], r["seconds"], rows[reference][k]["seconds"])
                    for k, r in rows[method].items()
                    if k in rows[reference] and closed(r) and closed(rows[reference][k])]
            found = compare(both, f"{method} / {reference}")
            if found:
                results.append(found)
            own = [(r["border_edges"], r["seconds"], rows[reference][k]["seconds"])
                   for k, r in rows[method].items()
                   if k in rows[reference] and closed(r) and closed(rows[reference][k])
                   and r.get("used_method") == method]
            if own and len(own) != len(both):
                found = compare(own, f"{method} (own fill) / {reference}")
                if found:
                    results.append(found)

    header = ("| methods | holes | median s | reference median s | ratio of medians | median ratio "
              "| worst ratio | time slope | reference slope | ratio slope (95% interval) | "
              + " | ".join(f"ratio {name} edges" for name, _, _ in results[0]["by_class"]) + " |")
    print(header)
    print("|" + "---|" * (header.count("|") - 1))
    for r in results:
        lo = r["slope_ratio"] - 1.96 * r["slope_ratio_error"]
        hi = r["slope_ratio"] + 1.96 * r["slope_ratio_error"]
        classes = " | ".join(f"{median:.2f}x ({count})" if count else "-"
                             for _, count, median in r["by_class"])
        print(f"| {r['label']} | {r['holes']} | {r['method_median']:.3g} | "
              f"{r['reference_median']:.3g} | {r['ratio_of_medians']:.2f}x | "
              f"{r['median_ratio']:.2f}x | {r['worst_ratio']:.1f}x | {r['slope_method']:.2f} | "
              f"{r['slope_reference']:.2f} | {r['slope_ratio']:+.2f} ({lo:+.2f}, {hi:+.2f}) | "
              f"{classes} |")


if __name__ == "__main__":
    main()
