#!/usr/bin/env python3
# Copyright (c) 2026 Mesh_repair developers.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Plots of `mesh_repair bench holes` results (doc/bench_holes.md).

usage: plot_bench.py RESULTS.jsonl OUT_DIR

Writes into OUT_DIR, one small PNG each:
  bar_<metric>.png     median per method (bar) and worst (black tick), one per metric;
  error_vs_size.png    Einf / diagonal against the hole's border edge count, per method;
  error_vs_radius.png  median Einf / diagonal against the requested radius, per method.
Needs Debian's python3-matplotlib; without it prints a warning and exits 0, so the benchmark's
results and table stand on their own.
"""
import json
import math
import os
import sys

METRICS = [
    ("e1_rel", "E1 / diagonal", True),
    ("e2_rel", "E2 / diagonal", True),
    ("einf_rel", "Einf / diagonal", True),
    ("hausdorff_rel", "Hausdorff / diagonal", True),
    ("normal_deviation_max_deg", "max normal deviation (deg)", True),
    ("min_alpha", "min alpha (patch)", False),
    ("min_angle_deg", "min angle (deg, patch)", False),
    ("seconds", "fill time per hole (s)", True),
]


def finite(value):
    return isinstance(value, (int, float)) and math.isfinite(value)


def median(values):
    values = sorted(values)
    n = len(values)
    if n == 0:
        return float("nan")
    return values[n // 2] if n % 2 else 0.5 * (values[n // 2 - 1] + values[n // 2])


def read_rows(path):
    rows = []
    with open(path) as stream:
        for line in stream:
            line = line.strip()
            if line:
                rows.append(json.loads(line))
    return rows


def methods_in_order(rows):
    order = []
    for row in rows:
        if row["method"] not in order:
            order.append(row["method"])
    return order


def bar_chart(plt, rows, methods, key, label, larger_is_worse, out_dir):
    medians, worsts = [], []
    for method in methods:
        values = [r[key] for r in rows if r["method"] == method and finite(r.get(key))]
        medians.append(median(values) if values else 0.0)
        if values:
            worsts.append(max(values) if larger_is_worse else min(values))
        else:
            worsts.append(float("nan"))
    figure, axes = plt.subplots(figsize=(4.8, 3.0), dpi=100)
    positions = range(len(methods))
    axes.bar(positions, medians, color="#4c72b0", label="median")
    axes.scatter(positions, worsts, color="black", marker="_", s=200, label="worst", zorder=3)
    axes.set_xticks(list(positions))
    axes.set_xticklabels(methods, rotation=30, ha="right", fontsize=7)
    axes.set_ylabel(label, fontsize=8)
    axes.tick_params(axis="y", labelsize=7)
    axes.set_title(label, fontsize=8)
    axes.legend(fontsize=7)
    figure.tight_layout()
    figure.savefig(os.path.join(out_dir, "bar_%s.png" % key))
    plt.close(figure)


def error_vs_size(plt, rows, methods, out_dir):
    figure, axes = plt.subplots(figsize=(4.8, 3.2), dpi=100)
    for method in methods:
        points = [(r["border_edges"], r["einf_rel"]) for r in rows
                  if r["method"] == method and finite(r.get("einf_rel")) and r["einf_rel"] > 0]
        if points:
            axes.scatter([p[0] for p in points], [p[1] for p in points], s=8, label=method)
    axes.set_yscale("log")
    axes.set_xlabel("border edges of the hole", fontsize=8)
    axes.set_ylabel("Einf / diagonal", fontsize=8)
    axes.tick_params(labelsize=7)
    axes.legend(fontsize=6)
    figure.tight_layout()
    figure.savefig(os.path.join(out_dir, "error_vs_size.png"))
    plt.close(figure)


def error_vs_radius(plt, rows, methods, out_dir):
    radii = sorted({r["radius"] for r in rows})
    figure, axes = plt.subplots(figsize=(4.8, 3.2), dpi=100)
    for method in methods:
        xs, ys = [], []
        for radius in radii:
            values = [r["einf_rel"] for r in rows if r["method"] == method
                      and r["radius"] == radius and finite(r.get("einf_rel"))]
            if values:
                xs.append(radius)
                ys.append(median(values))
        if xs:
            axes.plot(xs, ys, marker="o", label=method)
    axes.set_xlabel("hole radius / diagonal", fontsize=8)
    axes.set_ylabel("median Einf / diagonal", fontsize=8)
    if all(y > 0 for line in axes.get_lines() for y in line.get_ydata()):
        axes.set_yscale("log")
    axes.tick_params(labelsize=7)
    axes.legend(fontsize=6)
    figure.tight_layout()
    figure.savefig(os.path.join(out_dir, "error_vs_radius.png"))
    plt.close(figure)


def main(argv):
    if len(argv) != 3:
        sys.stderr.write(__doc__)
        return 2
    results, out_dir = argv[1], argv[2]
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        sys.stderr.write("plot_bench.py: warning: matplotlib is not installed "
                         "(apt-get install python3-matplotlib); no plots written\n")
        return 0
    try:
        rows = read_rows(results)
    except (OSError, ValueError) as error:
        sys.stderr.write("plot_bench.py: cannot read %s: %s\n" % (results, error))
        return 1
    if not rows:
        sys.stderr.write("plot_bench.py: warning: %s holds no results; no plots\n" % results)
        return 0
    os.makedirs(out_dir, exist_ok=True)
    methods = methods_in_order(rows)
    for key, label, larger_is_worse in METRICS:
        bar_chart(plt, rows, methods, key, label, larger_is_worse, out_dir)
    error_vs_size(plt, rows, methods, out_dir)
    error_vs_radius(plt, rows, methods, out_dir)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
