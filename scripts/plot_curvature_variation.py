#!/usr/bin/python3
"""Box plots of the curvature-variation benchmark (bench_curvature_variation --csv FILE).

Usage: scripts/plot_curvature_variation.py results.csv doc/images/curvature_variation
Writes PREFIX_jump.png and PREFIX_einf.png. Needs Debian's python3-matplotlib.
"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main():
    rows = list(csv.DictReader(open(sys.argv[1])))
    prefix = sys.argv[2]
    methods = []
    for r in rows:
        if r["method"] not in methods:
            methods.append(r["method"])
    for column, label, name in [("curvature_jump", "curvature jump x diagonal", "jump"),
                                ("einf", "Einf / diagonal", "einf")]:
        data = [[float(r[column]) for r in rows if r["method"] == m] for m in methods]
        fig, ax = plt.subplots(figsize=(7, 3.2), dpi=80)
        ax.boxplot(data, vert=False, labels=methods)
        ax.set_xscale("log")
        ax.set_xlabel(label)
        fig.tight_layout()
        fig.savefig(f"{prefix}_{name}.png")


if __name__ == "__main__":
    main()
