#!/usr/bin/env python3
"""Figures for a ddb-compare output folder (paper, Section 5), from its CSV/JSON only.

Usage: plot_compare.py OUT_DIR

Always:  casimir_vs_t.png   relative Casimir drift |C(t) - C(0)| / |C(0)|, every method
                            (matrix systems: the spectrum's |lambda(t) - lambda(0)| / |lambda(0)|)
Sweep:   error_vs_h.png (with slope guides h^p for the orders p of the methods, taken
         from summary.json), work_precision.png     (if error_vs_h.csv exists)
Rigid body with an isolated minimum (Scenarios A, B):
         sphere_trajectory.png (with the limit points +-|M0| e_i),
         distance_to_limit_points.png, error_vs_reference.png
Rigid body with I1 = I2 > I3 (Scenario C):
         sphere_trajectory.png (with the great circle of minimum energy),
         distance_to_great_circle.png

Every method has its own colour, line style and marker. Log axes cannot show an
exact 0: such points (round-off cancelling exactly, or the common initial state)
are left out, and the figure says so.
"""
import csv
import json
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.lines import Line2D  # noqa: E402

# colour, line style, marker: unique per method; families share a legend group.
STYLE = {
    "ddb-cay": dict(color="tab:blue", ls="-", marker="o"),
    "ddb-exp": dict(color="tab:orange", ls="--", marker="s"),
    "ddb-exp-exact": dict(color="tab:brown", ls=":", marker="^"),
    "ddb-cay-implicit": dict(color="tab:green", ls="-.", marker="p"),
    "ddb-exp-implicit": dict(color="teal", ls=(0, (3, 1, 1, 1)), marker="8"),
    "sddb-paper-cay": dict(color="hotpink", ls="-.", marker="v"),
    "sddb-paper-exp": dict(color="goldenrod", ls=(0, (5, 1, 1, 1, 1, 1)), marker="<"),
    "sddb-cay": dict(color="tab:cyan", ls="-", marker="D"),
    "sddb-exp": dict(color="tab:olive", ls="--", marker="P"),
    "ddb4-cay": dict(color="navy", ls="-.", marker="X"),
    "ddb4-exp": dict(color="darkgreen", ls=":", marker="*"),
    "ddb6-exp": dict(color="black", ls=(0, (8, 2)), marker="h"),
    "rk4": dict(color="tab:red", ls="-", marker=">"),
    "lobatto3c": dict(color="tab:purple", ls="--", marker="d"),
    "reference": dict(color="0.55", ls="-", marker="", lw=2.2),
}
GROUPS = [
    ("DDB, order 1", ["ddb-cay", "ddb-exp", "ddb-exp-exact"]),
    ("linearly implicit DDB, order 1", ["ddb-cay-implicit", "ddb-exp-implicit"]),
    ("paper's symmetric DDB, order 1", ["sddb-paper-cay", "sddb-paper-exp"]),
    ("symmetric DDB, order 2", ["sddb-cay", "sddb-exp"]),
    ("compositions, order 4 / 6", ["ddb4-cay", "ddb4-exp", "ddb6-exp"]),
    ("Runge–Kutta (no Casimir)", ["rk4", "lobatto3c"]),
    ("reference", ["reference"]),
]
ORDER = [m for _, ms in GROUPS for m in ms]
NOTE_ZEROS = "exact zeros cannot be drawn on a log axis and are left out"
NORM_REF = r"$\Vert M_N - M_N^{\mathrm{ref}}\Vert$"
MATRIX_SYSTEMS = {"manakov": "M", "zeitlin": "W"}


def describe(summary):
    """'manakov, N = 5, α = 0.5, h = 0.1' or 'rigid-body, scenario A, α = 0.5, h = 0.1'."""
    system, p = summary["system"], summary.get("parameters", {})
    parts = [system]
    if system in MATRIX_SYSTEMS:
        parts.append(f"N = {p['n']}")
        if system == "zeitlin":
            parts.append(f"init {p['init']}")
    elif summary.get("scenario") not in (None, "none"):
        parts.append(f"scenario {summary['scenario']}")
    if "alpha" in p:
        parts.append(f"α = {p['alpha']:g}")
    return ", ".join(parts)


def error_label(summary):
    """The final error's symbol: ‖M_N − M_N^ref‖ (Frobenius for a matrix state)."""
    letter = MATRIX_SYSTEMS.get(summary["system"])
    if letter is None:
        return NORM_REF
    return rf"$\Vert {letter}_N - {letter}_N^{{\mathrm{{ref}}}}\Vert_F$"


def style(name, index=0, dense=True):
    """Line keywords for a method; on dense curves the markers are spread out and
    shifted per method so that they do not sit on top of each other."""
    s = dict(STYLE.get(name, dict(color="k", ls="-", marker=".")))
    s.setdefault("lw", 1.1)
    if dense and s.get("marker"):
        s["markevery"] = (0.011 * (index % 9), 0.1)
    s["ms"] = 5 if dense else 4
    return s


def sort_methods(names):
    return sorted(names, key=lambda m: ORDER.index(m) if m in ORDER else len(ORDER))


def read_csv(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    return {k: [float(r[k]) for r in rows] for k in rows[0]} if rows else {}


def save(fig, out, name):
    path = os.path.join(out, name)
    tmp = path + ".tmp.png"
    fig.savefig(tmp, dpi=110, bbox_inches="tight")
    os.replace(tmp, path)
    plt.close(fig)
    print("wrote", path)


def grouped_legend(ax, names, **kw):
    """Legend outside the axes, right, grouped by method family with a header each."""
    handles, labels = ax.get_legend_handles_labels()
    by_label = dict(zip(labels, handles))
    hs, ls = [], []
    for title, members in GROUPS + [("other", [n for n in names if n not in ORDER])]:
        present = [m for m in members if m in by_label]
        if not present:
            continue
        hs.append(Line2D([], [], ls="none"))
        ls.append(f"$\\bf{{{title.replace(' ', '~')}}}$" if False else title + ":")
        for m in present:
            hs.append(by_label[m])
            ls.append("  " + m)
    leg = ax.legend(hs, ls, loc="upper left", bbox_to_anchor=(1.01, 1.0), fontsize=8,
                    frameon=False, handlelength=3.2, borderaxespad=0.0, **kw)
    for text, label in zip(leg.get_texts(), ls):
        if not label.startswith("  "):
            text.set_fontweight("bold")
    return leg


def positive(xs, ys):
    """(x, y) with y > 0 and finite, plus how many y were exactly 0."""
    zeros = sum(1 for y in ys if y == 0.0)
    pts = [(x, y) for x, y in zip(xs, ys) if y > 0.0 and math.isfinite(y)]
    return [p[0] for p in pts], [p[1] for p in pts], zeros


def footnote(fig, text):
    fig.text(0.01, -0.01, text, fontsize=8, color="0.3", ha="left", va="top")


def plot_casimirs(out, traj, summary):
    """Relative Casimir drift of every method (the Casimir value itself, a flat line
    at |M0| for every Casimir-preserving method, says nothing more). A matrix system's
    CSV holds the spectrum's relative drift itself (column casimir_drift)."""
    fig, ax = plt.subplots(figsize=(9.5, 5))
    names = sort_methods(traj)
    any_zero = False
    matrix = summary["system"] in MATRIX_SYSTEMS
    for i, name in enumerate(names):
        d = traj[name]
        if matrix:
            ts, ys, zeros = positive(d["t"][1:], d["casimir_drift"][1:])
            any_zero |= zeros > 0
            ax.semilogy(ts, ys, label=name, **style(name, i))
            continue
        for col in [k for k in d if k.startswith("casimir")]:
            c0 = d[col][0]
            scale = abs(c0) if c0 != 0 else 1.0
            dev = [abs(c - c0) / scale for c in d[col]]
            ts, ys, zeros = positive(d["t"][1:], dev[1:])
            any_zero |= zeros > 0
            label = name if col == "casimir" else f"{name} {col}"
            ax.semilogy(ts, ys, label=label, **style(name, i))
    ax.axhline(2.22e-16, color="0.3", lw=0.8, ls=(0, (1, 3)))
    ax.annotate("machine ε", (1.0, 2.22e-16), xycoords=("axes fraction", "data"),
                xytext=(3, 0), textcoords="offset points", fontsize=8, color="0.3",
                va="center", ha="left")
    ax.set_xlabel("time t")
    where = f"{describe(summary)}, h = {summary['h']:g}"
    if matrix:
        letter = MATRIX_SYSTEMS[summary["system"]]
        ax.set_ylabel(r"relative spectrum drift  $\Vert\lambda(t) - \lambda(0)\Vert\,/\,"
                      r"\Vert\lambda(0)\Vert$")
        ax.set_title(f"Casimir drift ({where}):\nDDB keeps the spectrum λ of {letter} "
                     "to round-off, Runge–Kutta methods drift")
    elif summary["system"] == "rigid-body":
        ax.set_ylabel(r"relative Casimir drift  $|C(t) - C(0)|\,/\,|C(0)|$,  $C = \Vert M\Vert$")
        ax.set_title(f"Casimir drift ({where}):\n"
                     "DDB keeps ‖M‖ to round-off, Runge–Kutta methods drift")
    else:
        ax.set_ylabel(r"relative Casimir drift  $|C_i(t) - C_i(0)|\,/\,|C_i(0)|$")
        ax.set_title(f"Casimir drift ({where}):\n"
                     "DDB keeps both Casimirs to round-off, Runge–Kutta methods drift")
    ax.grid(True, which="major", alpha=0.3)
    grouped_legend(ax, names)
    if any_zero:
        footnote(fig, f"Drift exactly 0 at some steps (round-off cancels): {NOTE_ZEROS}.")
    save(fig, out, "casimir_vs_t.png")


def slope_guides(ax, curves, orders):
    """Slope guides h^p, one for each order p > 0 of the methods (`orders`: method ->
    order, from summary.json), one decade of h long, each next to the methods of that
    order: O(h) above them, higher orders below them (factor 4), at the
    smallest step sizes where those methods are still above round-off (error > 30 x the smallest error
    of the figure)."""
    import numpy as np

    floor = 30 * min(e for c in curves.values() for _, e in c) if curves else 0.0
    for p in sorted({orders.get(m, 0) for m in curves} - {0}):
        group = {m: dict(c) for m, c in curves.items() if orders.get(m) == p}
        if not group:
            continue
        hs = sorted(set.intersection(*[set(g) for g in group.values()]))
        hs = [h for h in hs if all(g[h] > floor for g in group.values())]
        if len(hs) < 2:
            continue
        h_lo = hs[0]
        h_hi = min(hs[-1], h_lo * 10)
        h = np.geomspace(h_lo, h_hi, 10)
        pick = max if p == 1 else min
        factor = 4.0 if p == 1 else 0.25
        # envelope of the group on the window, then a line of slope p just outside it
        env = [pick(g[x] for g in group.values()) for x in hs if h_lo <= x <= h_hi]
        xs = [x for x in hs if h_lo <= x <= h_hi]
        if len(xs) < 2 or abs(math.log(env[-1] / env[0]) / math.log(xs[-1] / xs[0]) - p) > 0.75:
            continue  # the data do not show this order here (round-off, or not asymptotic)
        shifts = [e / x ** p for x, e in zip(xs, env)]
        c = (max(shifts) if p == 1 else min(shifts)) * factor
        ax.plot(h, c * h ** p, color="0.2", lw=2.0, ls="-", alpha=0.55, zorder=1,
                solid_capstyle="butt")
        txt = "slope 1: O(h)" if p == 1 else f"slope {p}: O(h$^{p}$)"
        ax.annotate(txt, (h[-1], c * h[-1] ** p), xytext=(4, 0 if p == 1 else -4),
                    textcoords="offset points", fontsize=9, color="0.15",
                    ha="left", va="top" if p != 1 else "bottom",
                    bbox=dict(boxstyle="round,pad=0.15", fc="white", ec="none", alpha=0.85))


def plot_sweep(out, path, summary):
    title = describe(summary)
    orders = {m: e.get("order", 0) for m, e in summary["methods"].items()}
    err = "error in the final state  " + error_label(summary)
    rows = list(csv.DictReader(open(path, newline="")))
    methods = sort_methods({r["method"] for r in rows})
    fig, ax = plt.subplots(figsize=(9.5, 6))
    fig2, ax2 = plt.subplots(figsize=(9.5, 6))
    curves, omitted = {}, []
    for i, m in enumerate(methods):
        pts = [(float(r["h"]), float(r["err_final"]), float(r["runtime_s"])) for r in rows
               if r["method"] == m]
        bad = [p for p in pts if not (math.isfinite(p[1]) and p[1] > 0)]
        if bad:
            omitted.append(f"{m} ({len(bad)})")
        pts = sorted(p for p in pts if p not in bad)
        if not pts:
            continue
        s = style(m, i, dense=False)
        ax.loglog([p[0] for p in pts], [p[1] for p in pts], label=m, **s)
        ax2.loglog([p[2] for p in pts], [p[1] for p in pts], label=m, **s)
        curves[m] = [(p[0], p[1]) for p in pts]
    slope_guides(ax, curves, orders)
    t_end = summary["t_end_requested"]
    ax.set_xlabel("step size h")
    ax.set_ylabel(err)
    ax.set_title(f"Convergence: error at t = {t_end:g} vs step size ({title})\n"
                 "grey bars: slopes of the methods' orders; a flat tail at small h is round-off")
    ax2.set_xlabel("wall time per run (s)")
    ax2.set_ylabel(err)
    ax2.set_title(f"Work–precision: error at t = {t_end:g} vs cost ({title})\n"
                  "one point per step size; lower left is better")
    for a in (ax, ax2):
        a.grid(True, which="major", alpha=0.3)
        grouped_legend(a, methods)
    if omitted:
        for f in (fig, fig2):
            footnote(f, "Final error exactly 0 or not finite, left out: " + ", ".join(omitted))
    save(fig, out, "error_vs_h.png")
    save(fig2, out, "work_precision.png")


def plot_sphere(out, traj, name, radius, largest, circle, scenario):
    import numpy as np

    d = traj[name]
    fig = plt.figure(figsize=(7.5, 7))
    ax = fig.add_subplot(projection="3d")
    u, v = np.mgrid[0:2 * np.pi:40j, 0:np.pi:20j]
    ax.plot_wireframe(radius * np.cos(u) * np.sin(v), radius * np.sin(u) * np.sin(v),
                      radius * np.cos(v), color="0.85", lw=0.4)
    ax.plot(d["m1"], d["m2"], d["m3"], color="tab:blue", lw=0.9,
            label=f"$M_k$, {name} (h = {traj['_h']:g})")
    ax.scatter([d["m1"][0]], [d["m2"][0]], [d["m3"][0]], color="tab:green", s=110,
               marker="o", edgecolors="k", depthshade=False, label="start $M_0$", zorder=5)
    ax.scatter([d["m1"][-1]], [d["m2"][-1]], [d["m3"][-1]], color="tab:red", s=90,
               marker="s", edgecolors="k", depthshade=False, label=f"end $M_N$ (t = {d['t'][-1]:g})", zorder=5)
    if circle:
        th = np.linspace(0, 2 * np.pi, 200)
        ax.plot(radius * np.cos(th), radius * np.sin(th), 0 * th, color="k", lw=2.0, ls="--",
                label=r"great circle $\{M_3 = 0,\ \Vert M\Vert = \Vert M_0\Vert\}$")
    else:
        p = np.zeros((2, 3))
        p[0, largest], p[1, largest] = radius, -radius
        ax.scatter(p[:, 0], p[:, 1], p[:, 2], color="k", marker="*", s=180, depthshade=False,
                   label=f"limit points $\\pm\\Vert M_0\\Vert e_{largest + 1}$", zorder=6)
    lim = radius * 1.05
    ax.set_xlim(-lim, lim)
    ax.set_ylim(-lim, lim)
    ax.set_zlim(-lim, lim)
    ax.set_box_aspect((1, 1, 1), zoom=0.88)
    ax.set_xlabel("$M_1$")
    ax.set_ylabel("$M_2$")
    ax.set_zlabel("$M_3$")
    ax.view_init(elev=22, azim=-35 if not circle else -60)
    ax.set_title(f"Scenario {scenario}: $M_k$ on the Casimir sphere "
                 f"$\\Vert M\\Vert = \\Vert M_0\\Vert$ = {radius:.4g}")
    ax.legend(loc="upper left", bbox_to_anchor=(0.0, -0.02), fontsize=9, ncol=2,
              frameon=False)
    save(fig, out, "sphere_trajectory.png")


def plot_rigid_body(out, traj, summary):
    inertia = summary["parameters"]["inertia"]
    scenario = summary.get("scenario", "")
    ref = traj.get("reference")
    ddb_name = "ddb-cay" if "ddb-cay" in traj else next((n for n in traj if n.startswith("ddb")), None)
    if ddb_name is None:
        return
    ddb = traj[ddb_name]
    radius = math.sqrt(ddb["m1"][0] ** 2 + ddb["m2"][0] ** 2 + ddb["m3"][0] ** 2)
    order = sorted(range(3), key=lambda i: inertia[i])
    largest, second = order[2], order[1]
    circle = abs(inertia[largest] - inertia[second]) < 1e-12
    traj["_h"] = summary.get("h", float("nan"))
    plot_sphere(out, traj, ddb_name, radius, largest, circle, scenario)
    del traj["_h"]
    names = sort_methods(traj)
    title = f"scenario {scenario}, h = {summary.get('h', float('nan')):g}"

    def last_part(d):
        n = len(d["t"])
        return range(int(0.8 * n), n)

    M = lambda d, k: [d["m1"][k], d["m2"][k], d["m3"][k]]  # noqa: E731
    if not circle:
        axis = largest
        fig, ax = plt.subplots(figsize=(9.5, 5))
        zeros = 0
        for i, name in enumerate(names):
            d = traj[name]
            ks = last_part(d)
            dist = []
            for k in ks:
                m = M(d, k)
                dist.append(min(math.dist(m, [s * radius if j == axis else 0.0 for j in range(3)])
                                for s in (1.0, -1.0)))
            ts, ys, z = positive([d["t"][k] for k in ks], dist)
            zeros += z
            ax.semilogy(ts, ys, label=name, **style(name, i))
        ax.set_xlabel("time t (last 20% of the run)")
        ax.set_ylabel(f"$\\min_\\pm \\Vert M(t) \\mp \\Vert M_0\\Vert e_{axis + 1}\\Vert$")
        ax.set_title(f"Distance to the nearer limit point $\\pm\\Vert M_0\\Vert e_{axis + 1}$ "
                     f"(energy minimum on the sphere), {title}")
        ax.grid(True, which="major", alpha=0.3)
        grouped_legend(ax, names)
        if zeros:
            footnote(fig, f"Some distances are exactly 0: {NOTE_ZEROS}.")
        save(fig, out, "distance_to_limit_points.png")
        if ref is not None:
            fig, ax = plt.subplots(figsize=(9.5, 5))
            others = [n for n in names if n != "reference"]
            for i, name in enumerate(others):
                d = traj[name]
                n = min(len(d["t"]), len(ref["t"]))
                err = [math.dist(M(d, k), M(ref, k)) for k in range(n)]
                ts, ys, _ = positive(d["t"][:n], err)
                ax.semilogy(ts, ys, label=name, **style(name, i))
            ax.set_xlabel("time t")
            ax.set_ylabel(r"$\Vert M(t) - M^{\mathrm{ref}}(t)\Vert$")
            ax.set_title(f"Error against the reference solution (RKF 7(8), tol 1e-13), {title}")
            ax.grid(True, which="major", alpha=0.3)
            grouped_legend(ax, others)
            footnote(fig, f"At t = 0 every method equals the reference; {NOTE_ZEROS}.")
            save(fig, out, "error_vs_reference.png")
    else:
        smallest = order[0]
        plane = [i for i in range(3) if i != smallest]
        fig, axes = plt.subplots(2, 1, figsize=(9.5, 8), sharex=True)
        zeros = 0
        for i, name in enumerate(names):
            d = traj[name]
            ks = last_part(d)
            to_circle, to_plane = [], []
            for k in ks:
                m = M(d, k)
                rho = math.hypot(m[plane[0]], m[plane[1]])
                to_circle.append(math.hypot(m[smallest], rho - radius))
                to_plane.append(abs(m[smallest]))
            t_all = [d["t"][k] for k in ks]
            ts, ys, z1 = positive(t_all, to_circle)
            axes[0].semilogy(ts, ys, label=name, **style(name, i))
            ts, ys, z2 = positive(t_all, to_plane)
            axes[1].semilogy(ts, ys, label=name, **style(name, i))
            zeros += z1 + z2
        c = smallest + 1
        axes[0].set_title(f"Distance to the great circle of minimum energy "
                          f"$\\{{M_{c} = 0,\\ \\Vert M\\Vert = \\Vert M_0\\Vert\\}}$, {title}")
        axes[0].set_ylabel(f"$\\sqrt{{M_{c}^2 + (\\rho - \\Vert M_0\\Vert)^2}}$")
        axes[0].text(0.01, 0.03, f"$\\rho = \\sqrt{{M_{plane[0] + 1}^2 + M_{plane[1] + 1}^2}}$",
                     transform=axes[0].transAxes, fontsize=9, color="0.3")
        axes[1].set_title(f"Distance to the plane $M_{c} = 0$")
        axes[1].set_ylabel(f"$|M_{c}(t)|$")
        axes[1].set_xlabel("time t (last 20% of the run)")
        for a in axes:
            a.grid(True, which="major", alpha=0.3)
        grouped_legend(axes[0], names)
        if zeros:
            footnote(fig, f"Some distances are exactly 0: {NOTE_ZEROS}.")
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
    plot_casimirs(out, traj, summary)
    sweep = os.path.join(out, "error_vs_h.csv")
    if os.path.exists(sweep):
        plot_sweep(out, sweep, summary)
    if summary["system"] == "rigid-body":
        plot_rigid_body(out, traj, summary)


if __name__ == "__main__":
    main()
