#!/usr/bin/env python3
"""Figures for a ddb-compare output folder (paper, Section 5), from its CSV/JSON only.

Usage: plot_compare.py OUT_DIR

Always:  casimir_vs_t.png (all methods; DDB and reference only)
Sweep:   error_vs_h.png, work_precision.png          (if error_vs_h.csv exists)
Rigid body with an isolated minimum (Scenario B-like):
         sphere_trajectory.png, distance_to_limit_points.png, error_vs_reference.png
Rigid body with I1 = I2 > I3 (Scenario C-like):
         sphere_trajectory.png, distance_to_great_circle.png
"""
import csv
import json
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

STYLE = {
    "ddb-cay": dict(color="tab:blue", ls="-"),
    "ddb-exp": dict(color="tab:orange", ls="--"),
    "ddb-exp-exact": dict(color="tab:brown", ls=":"),
    "sddb-cay": dict(color="tab:cyan", ls="-"),
    "sddb-exp": dict(color="tab:olive", ls="--"),
    "ddb4-cay": dict(color="navy", ls="-"),
    "ddb4-exp": dict(color="darkgreen", ls="--"),
    "ddb6-exp": dict(color="black", ls="-."),
    "sddb-paper-cay": dict(color="tab:pink", ls="-"),
    "sddb-paper-exp": dict(color="tab:pink", ls="--"),
    "rk4": dict(color="tab:red", ls="-"),
    "lobatto3c": dict(color="tab:purple", ls="-"),
    "reference": dict(color="tab:gray", ls="-"),
}


def style(name):
    return STYLE.get(name, {})


def read_csv(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    return {k: [float(r[k]) for r in rows] for k in rows[0]} if rows else {}


def save(fig, out, name):
    path = os.path.join(out, name)
    tmp = path + ".tmp.png"
    fig.tight_layout()
    fig.savefig(tmp, dpi=110)
    os.replace(tmp, path)
    plt.close(fig)
    print("wrote", path)


def casimir_columns(data):
    return [k for k in data if k.startswith("casimir")]


def plot_casimirs(out, traj):
    fig, axes = plt.subplots(2, 1, figsize=(8, 7))
    for name, d in traj.items():
        for col in casimir_columns(d):
            c0 = d[col][0]
            scale = abs(c0) if c0 != 0 else 1.0
            dev = [max(abs(c - c0) / scale, 1e-18) for c in d[col]]
            axes[0].semilogy(d["t"], dev, label=f"{name} {col}", **style(name))
    axes[0].set_title("relative Casimir deviation |C(t) - C(0)| / |C(0)|, all methods")
    axes[0].set_xlabel("t")
    axes[0].legend(fontsize=7)
    for name, d in traj.items():
        if name.startswith("ddb") or name.startswith("sddb") or name == "reference":
            for col in casimir_columns(d):
                axes[1].plot(d["t"], d[col], label=f"{name} {col}", **style(name))
    axes[1].set_title("Casimir value, DDB methods and reference")
    axes[1].set_xlabel("t")
    axes[1].ticklabel_format(useOffset=False)
    axes[1].legend(fontsize=7)
    save(fig, out, "casimir_vs_t.png")


def plot_sweep(out, path, title):
    rows = list(csv.DictReader(open(path, newline="")))
    methods = sorted({r["method"] for r in rows}, key=lambda m: list(STYLE).index(m) if m in STYLE else 99)
    fig, ax = plt.subplots(figsize=(7, 5))
    fig2, ax2 = plt.subplots(figsize=(7, 5))
    for m in methods:
        pts = [(float(r["h"]), float(r["err_final"]), float(r["runtime_s"])) for r in rows
               if r["method"] == m and math.isfinite(float(r["err_final"])) and float(r["err_final"]) > 0]
        if not pts:
            continue
        pts.sort()
        ax.loglog([p[0] for p in pts], [p[1] for p in pts], marker="o", ms=3, label=m, **style(m))
        ax2.loglog([p[2] for p in pts], [p[1] for p in pts], marker="o", ms=3, label=m, **style(m))
    ax.set_xlabel("h")
    ax.set_ylabel("‖M_N − M_N^ref‖")
    ax.set_title(f"error in the final momentum vs h ({title})")
    ax.legend(fontsize=8)
    ax2.set_xlabel("CPU time (s)")
    ax2.set_ylabel("‖M_N − M_N^ref‖")
    ax2.set_title(f"work–precision ({title})")
    ax2.legend(fontsize=8)
    save(fig, out, "error_vs_h.png")
    save(fig2, out, "work_precision.png")


def sphere(ax, radius):
    import numpy as np

    u, v = np.mgrid[0:2 * np.pi:40j, 0:np.pi:20j]
    ax.plot_wireframe(radius * np.cos(u) * np.sin(v), radius * np.sin(u) * np.sin(v),
                      radius * np.cos(v), color="0.85", lw=0.4)


def plot_rigid_body(out, traj, summary):
    inertia = summary["parameters"]["inertia"]
    ref = traj.get("reference")
    ddb = traj.get("ddb-cay") or next((d for n, d in traj.items() if n.startswith("ddb")), None)
    if ddb is None:
        return
    radius = math.sqrt(ddb["m1"][0] ** 2 + ddb["m2"][0] ** 2 + ddb["m3"][0] ** 2)
    order = sorted(range(3), key=lambda i: inertia[i])
    largest, second = order[2], order[1]
    circle = abs(inertia[largest] - inertia[second]) < 1e-12
    fig = plt.figure(figsize=(6, 6))
    ax = fig.add_subplot(projection="3d")
    sphere(ax, radius)
    ax.plot(ddb["m1"], ddb["m2"], ddb["m3"], color="tab:blue", lw=0.8)
    ax.set_title("M_k on the Casimir sphere (DDB, Cayley)")
    save(fig, out, "sphere_trajectory.png")

    def last_part(d):
        n = len(d["t"])
        return range(int(0.8 * n), n)

    M = lambda d, k: [d["m1"][k], d["m2"][k], d["m3"][k]]  # noqa: E731
    if not circle:
        axis = largest
        fig, ax = plt.subplots(figsize=(8, 5))
        for name, d in traj.items():
            ks = last_part(d)
            dist = []
            for k in ks:
                m = M(d, k)
                dist.append(min(math.dist(m, [s * radius if i == axis else 0.0 for i in range(3)])
                                for s in (1.0, -1.0)))
            ax.semilogy([d["t"][k] for k in ks], [max(x, 1e-18) for x in dist], label=name, **style(name))
        ax.set_title(f"distance to the limit points ±‖M0‖e{axis + 1} (last 20% of the run)")
        ax.set_xlabel("t")
        ax.legend(fontsize=8)
        save(fig, out, "distance_to_limit_points.png")
        if ref is not None:
            fig, ax = plt.subplots(figsize=(8, 5))
            for name, d in traj.items():
                if name == "reference":
                    continue
                n = min(len(d["t"]), len(ref["t"]))
                err = [max(math.dist(M(d, k), M(ref, k)), 1e-18) for k in range(n)]
                ax.semilogy(d["t"][:n], err, label=name, **style(name))
            ax.set_title("‖M(t) − M_ref(t)‖")
            ax.set_xlabel("t")
            ax.legend(fontsize=8)
            save(fig, out, "error_vs_reference.png")
    else:
        smallest = order[0]
        plane = [i for i in range(3) if i != smallest]
        fig, axes = plt.subplots(2, 1, figsize=(8, 7))
        for name, d in traj.items():
            ks = last_part(d)
            to_circle, to_plane = [], []
            for k in ks:
                m = M(d, k)
                rho = math.hypot(m[plane[0]], m[plane[1]])
                to_circle.append(max(math.hypot(m[smallest], rho - radius), 1e-18))
                to_plane.append(max(abs(m[smallest]), 1e-18))
            ts = [d["t"][k] for k in ks]
            axes[0].semilogy(ts, to_circle, label=name, **style(name))
            axes[1].semilogy(ts, to_plane, label=name, **style(name))
        axes[0].set_title("distance to the great circle of minimum energy (last 20%)")
        axes[1].set_title(f"distance to the plane M{smallest + 1} = 0 (last 20%)")
        for a in axes:
            a.set_xlabel("t")
            a.legend(fontsize=8)
        save(fig, out, "distance_to_great_circle.png")


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    out = sys.argv[1]
    summary = json.load(open(os.path.join(out, "summary.json")))
    traj = {}
    for name in summary["methods"]:
        path = os.path.join(out, name + ".csv")
        if os.path.exists(path):
            traj[name] = read_csv(path)
    plot_casimirs(out, traj)
    sweep = os.path.join(out, "error_vs_h.csv")
    title = f"{summary['system']}, scenario {summary['scenario']}"
    if os.path.exists(sweep):
        plot_sweep(out, sweep, title)
    if summary["system"] == "rigid-body":
        plot_rigid_body(out, traj, summary)


if __name__ == "__main__":
    main()
