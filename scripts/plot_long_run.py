#!/usr/bin/env python3
"""Relative Casimir drift against the number of steps for long ddb-compare runs.

Usage: plot_long_run.py OUT.png LABEL=FOLDER [LABEL=FOLDER ...]
Each FOLDER holds a ddb-compare run with one method and --every K (docs/results/casimir-drift.md);
the curve is the largest |C_k - C_0| / |C_0| over the rows written up to step k.
"""
import csv
import glob
import json
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def drift_curve(folder):
    """Steps and running-maximum drift of the one method CSV in `folder`."""
    (path,) = [p for p in glob.glob(folder + "/*.csv") if not p.endswith("error_vs_h.csv")]
    h = json.load(open(folder + "/summary.json"))["h"]
    rows = list(csv.DictReader(open(path)))
    column = "casimir" if "casimir" in rows[0] else "casimir1"
    c0 = float(rows[0][column])
    steps, drifts, worst = [], [], 0.0
    for row in rows[1:]:
        worst = max(worst, abs(float(row[column]) - c0) / abs(c0))
        steps.append(round(float(row["t"]) / h))
        drifts.append(worst)
    return steps, drifts


def main():
    out = sys.argv[1]
    fig, ax = plt.subplots(figsize=(6.4, 4.2))
    for item in sys.argv[2:]:
        label, folder = item.split("=", 1)
        steps, drifts = drift_curve(folder)
        kept = [(k, d) for k, d in zip(steps, drifts) if d > 0]  # log axes: exact zeros omitted
        ax.loglog([k for k, _ in kept], [d for _, d in kept], marker=".", label=label)
    n = [1e5, 1e7]
    ax.loglog(n, [1.1e-16 * k ** 0.5 for k in n], "k:", label="random walk 1.1e-16·√k")
    ax.loglog(n, [2e-17 * k for k in n], "k--", label="linear 2e-17·k")
    ax.set_xlabel("steps k")
    ax.set_ylabel("max relative Casimir drift up to step k")
    first = json.load(open(sys.argv[2].split("=", 1)[1] + "/summary.json"))
    (method,) = first["methods"].keys()
    ax.set_title(f"{method}, scenario {first['scenario']}, h = {first['h']:g}: Casimir drift")
    ax.legend(fontsize=8)
    ax.grid(True, which="both", alpha=0.3)
    fig.tight_layout()
    fig.savefig(out, dpi=120)


if __name__ == "__main__":
    main()
