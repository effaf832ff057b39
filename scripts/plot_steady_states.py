#!/usr/bin/env python3
"""The figure of docs/guide/steady-states.md, from fluid-relax runs of one problem.

usage: plot_steady_states.py FIXED ADAPTIVE NEWTON [IMPLICIT] OUT.png

FIXED, ADAPTIVE, NEWTON and IMPLICIT are fluid-relax output folders (history.csv,
summary.json): fixed steps, --adaptive, --newton, and --adaptive with --method
ddb-cay-implicit (docs/guide/steady-states.md). Left: ||[P, W]||_F and the step h against the flow
time t for the time-stepping runs (one axis pair: ||[P, W]||_F on the left scale, h on the
right). Right: ||[P, W]||_F against the accepted step for all, with each run's steps and wall
time in its label (a Newton search has no time, and its steps cost more than a DDB step: the
wall times are the comparison).
"""
import csv
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def read_run(folder):
    with open(os.path.join(folder, "history.csv")) as f:
        rows = list(csv.DictReader(f))
    columns = {key: np.array([float(r[key]) for r in rows]) for key in rows[0]}
    with open(os.path.join(folder, "summary.json")) as f:
        summary = json.load(f)
    # The accepted step of each row: rows are every `every`-th state and the last.
    every = int(summary["every"])
    steps = np.minimum(np.arange(len(rows)) * every, int(summary["steps"]))
    steps[-1] = int(summary["steps"])
    return columns, summary, steps


def label(name, summary):
    return "%s: %d steps, %.3g s, r = %.2g" % (name, summary["steps"], summary["runtime_s"],
                                             summary["residual_final"])


def main():
    if len(sys.argv) not in (5, 6):
        sys.exit(__doc__)
    runs = [("fixed h = %g" % read_run(sys.argv[1])[1]["h"], read_run(sys.argv[1]), "tab:blue"),
            ("energy step control", read_run(sys.argv[2]), "tab:orange"),
            ("Newton on the orbit", read_run(sys.argv[3]), "tab:green")]
    if len(sys.argv) == 6:
        runs.append(("linearly implicit DDB, step control", read_run(sys.argv[4]), "tab:red"))
    first = runs[0][1][1]
    fig, (left, right) = plt.subplots(1, 2, figsize=(13, 4.8), layout="constrained")
    step_axis = left.twinx()
    for name, (columns, summary, _), color in [r for r in runs if not r[1][1]["newton"]]:
        t = columns["t"]
        keep = t > 0
        left.loglog(t[keep], columns["commutator_norm"][keep], color=color,
                    label=name + ": $\\|[P, W]\\|_F$")
        step_axis.loglog(t[keep], columns["h"][keep], color=color, linestyle=":", alpha=0.8,
                         label=name + ": h")
    left.set_xlabel("flow time t")
    left.set_ylabel("$\\|[P, W]\\|_F$ (solid)")
    step_axis.set_ylabel("step h (dotted)")
    lines = left.get_legend_handles_labels()
    more = step_axis.get_legend_handles_labels()
    left.legend(lines[0] + more[0], lines[1] + more[1], fontsize=8, loc="lower left")
    left.set_title("time stepping: $\\|[P, W]\\|_F$ and h against t")
    left.grid(alpha=0.3, which="both")
    for name, (columns, summary, steps), color in runs:
        keep = steps > 0
        right.loglog(steps[keep], columns["commutator_norm"][keep], color=color,
                     label=label(name, summary))
    fixed_final = runs[0][1][0]["commutator_norm"][-1]
    right.axhline(fixed_final, color="gray", linestyle="--", linewidth=0.8,
                  label="the fixed run's final $\\|[P, W]\\|_F$ = %.2g" % fixed_final)
    right.set_xlabel("accepted step (Newton: iteration)")
    right.set_ylabel("$\\|[P, W]\\|_F$")
    right.legend(fontsize=8, loc="lower left")
    right.set_title("all runs against their steps (wall times in the labels)")
    right.grid(alpha=0.3, which="both")
    fig.suptitle("Zeitlin fluid N = %d, alpha = %g, %s init (seed %s): relaxing to a steady "
                 "state; every accepted state on the orbit, no energy rise" %
                 (first["n"], first["alpha"], first["init"], first["seed"]))
    fig.savefig(sys.argv[-1], dpi=110)


if __name__ == "__main__":
    main()
