#!/usr/bin/env python3
"""Figures for a fluid-relax output folder (docs/reference/command-lines-and-files.md), from its
CSV/JSON files (and fluid.hdf5 for the spectrum).

Usage: plot_fluid.py OUT_DIR

vorticity_sphere.png  the vorticity on the sphere, initial and final, Mollweide projection,
                      one colour scale, evaluated from omega_initial.csv / omega_final.csv
spectrum.png          with --h5: the energy spectrum E_l of the first and last frames of
                      fluid.hdf5, log-log, with l^-3 and l^-5/3 slopes (needs h5py)
history.png           energy, enstrophy, ||[P,W]||_F (log) and spectrum drift (log, zeros
                      omitted) against t, from history.csv; for a Newton search (--newton),
                      whose rows all have t = 0 and no h, against the iteration k

The vorticity is omega(theta, phi) = sqrt(4 pi) sum omega_lm Y_lm(theta, phi), the function the
matrix quantises (systems/spherical_harmonic_grid.h: X_3 is cos theta), with the real spherical
harmonics of docs/reference/conventions.md §2 (theta colatitude, phi longitude):
  m > 0: sqrt(2) (-1)^m Re Y_l^m,  m < 0: sqrt(2) (-1)^m Im Y_l^|m|,  m = 0: Y_l^0,
Y_l^m being scipy's complex harmonics (Condon-Shortley phase), so that Y_10, Y_11, Y_1-1
are proportional to z, x, y.
"""
import csv
import json
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from scipy.special import sph_harm  # noqa: E402

# Harmonics above this degree are left out of the sphere figure (and the title says so):
# scipy's sph_harm (Debian 12's scipy 1.10) returns NaN for orders m >= 86, its normalisation
# overflowing, which drew an N = 128 run's figure blank.
L_MAX_PLOTTED = 85


def read_columns(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    return {k: np.array([float(r[k]) for r in rows]) for k in rows[0]} if rows else {}


def save(fig, out, name):
    path = os.path.join(out, name)
    tmp = path + ".tmp.png"
    fig.savefig(tmp, dpi=110)
    os.replace(tmp, path)
    plt.close(fig)
    print("wrote", path)


def vorticity(omega, theta, phi, l_max):
    """sqrt(4 pi) times the sum over l <= l_max of omega[(l, m)] Y_lm on the grid theta
    (colatitudes) x phi."""
    field = np.zeros((theta.size, phi.size))
    by_m = {}
    for (l, m), w in omega.items():
        if l <= l_max and w != 0.0:
            by_m.setdefault(abs(m), []).append((l, m, w))
    for m_abs, terms in by_m.items():
        cos_part = np.zeros(theta.size)
        sin_part = np.zeros(theta.size)
        for l, m, w in terms:
            # Y_l^|m| at longitude 0 is real: N_lm P_l^|m|(cos theta).
            y = sph_harm(m_abs, l, 0.0, theta).real
            if m == 0:
                cos_part += w * y
            elif m > 0:
                cos_part += w * math.sqrt(2.0) * (-1) ** m_abs * y
            else:
                sin_part += w * math.sqrt(2.0) * (-1) ** m_abs * y
        field += np.outer(cos_part, np.cos(m_abs * phi)) + np.outer(sin_part, np.sin(m_abs * phi))
    return math.sqrt(4.0 * math.pi) * field


def read_omega(path):
    columns = read_columns(path)
    return {(int(l), int(m)): w for l, m, w in zip(columns["l"], columns["m"], columns["omega"])}


def plot_sphere(out, summary):
    n = int(summary["n"])
    l_max = min(n - 1, L_MAX_PLOTTED)
    points = max(181, 4 * l_max + 1)
    latitude = np.linspace(-math.pi / 2, math.pi / 2, points)
    longitude = np.linspace(-math.pi, math.pi, 2 * points - 1)
    fields = [
        vorticity(read_omega(os.path.join(out, name)), math.pi / 2 - latitude, longitude, l_max)
        for name in ("omega_initial.csv", "omega_final.csv")
    ]
    limit = max(np.abs(f).max() for f in fields)
    fig = plt.figure(figsize=(12, 4.2), layout="constrained")
    titles = ["initial", "final, after %d Newton iterations" % summary["steps"]]
    if not summary.get("newton"):
        titles = ["initial, t = 0", "final, t = %.4g" % summary["t_end"]]
    for i, (field, title) in enumerate(zip(fields, titles)):
        ax = fig.add_subplot(1, 2, i + 1, projection="mollweide")
        mesh = ax.pcolormesh(longitude, latitude, field, cmap="RdBu_r", vmin=-limit, vmax=limit,
                             shading="auto", rasterized=True)
        ax.set_title(title)
        ax.set_xticklabels([])
        ax.grid(alpha=0.3)
    truncated = " (l <= %d shown)" % l_max if l_max < n - 1 else ""
    fig.suptitle("vorticity $\\omega(\\theta, \\varphi)$, N = %d, alpha = %g, %s, init %s%s" %
                 (n, summary["alpha"], summary["method"], summary["init"], truncated))
    fig.colorbar(mesh, ax=fig.axes, orientation="horizontal", fraction=0.06, shrink=0.5,
                 label="$\\omega$ (one scale for both)")
    save(fig, out, "vorticity_sphere.png")


def iterations(rows, summary):
    """The iteration k of each history row of a Newton search: every --every-th iteration
    from 0 and the last one, summary["steps"] (docs/reference/command-lines-and-files.md)."""
    every, last = int(summary["every"]), int(summary["steps"])
    k = list(range(0, last + 1, every))
    if k[-1] != last:
        k.append(last)
    if len(k) != rows:
        sys.exit("history.csv has %d rows, but a Newton search of %d iterations with --every %d "
                 "writes %d" % (rows, last, every, len(k)))
    return np.array(k, dtype=float)


def plot_history(out, summary):
    h = read_columns(os.path.join(out, "history.csv"))
    newton = bool(summary.get("newton"))
    t = iterations(h["energy"].size, summary) if newton else h["t"]
    fig, axes = plt.subplots(2, 2, figsize=(11, 7), sharex=True)
    axes[0, 0].plot(t, h["energy"], color="tab:blue")
    axes[0, 0].set_ylabel("energy E = Re tr(WP)/(2N)")
    axes[0, 1].plot(t, h["enstrophy"] - h["enstrophy"][0], color="tab:green")
    axes[0, 1].set_ylabel("enstrophy Z(t) - Z(0), Z(0) = %.6g" % h["enstrophy"][0])
    for ax, key, label in ((axes[1, 0], "commutator_norm", "$\\|[P, W]\\|_F$"),
                           (axes[1, 1], "spectrum_drift", "spectrum drift (relative)")):
        values = h[key]
        keep = values > 0  # zeros have no logarithm: omitted
        if keep.any():
            ax.semilogy(t[keep], values[keep], color="tab:red" if key == "spectrum_drift" else "k")
        else:
            ax.text(0.5, 0.5, "zero at every t", transform=ax.transAxes, ha="center")
        ax.set_ylabel(label + (" (zeros omitted)" if not keep.all() and keep.any() else ""))
        ax.set_xlabel("Newton iteration k" if newton else "t")
    for ax in axes.flat:
        ax.grid(alpha=0.3)
    steps = ("Newton search, %d iterations" % summary["steps"] if newton else
             "%s, h = %.4g, %d steps" % (summary["method"], summary["h"], summary["steps"]))
    fig.suptitle("N = %d, alpha = %g, %s, init %s" %
                 (summary["n"], summary["alpha"], steps, summary["init"]))
    fig.tight_layout()
    save(fig, out, "history.png")


def plot_spectrum(out, summary):
    """spectrum.png: the energy spectrum E_l of fluid.hdf5's first and last frames, log-log, with
    the l^-3 (enstrophy cascade) and l^-5/3 (energy cascade) slopes through the last frame's
    E_l at l = 4. Only for a file with the field diagnostics (run with --h5)."""
    path = os.path.join(out, "fluid.hdf5")
    if not os.path.exists(path):
        return
    try:
        import h5py
    except ImportError:
        print("plot_fluid.py: no spectrum.png: fluid.hdf5 needs h5py (Debian: python3-h5py)",
              file=sys.stderr)
        return
    with h5py.File(path, "r") as f:
        if "energy_spectrum" not in f or f["energy_spectrum"].shape[0] == 0:
            return
        spectra = f["energy_spectrum"][[0, -1]]
        times = f["time"][[0, -1]]
    l = np.arange(1, spectra.shape[1])
    fig, ax = plt.subplots(figsize=(6.4, 4.6))
    for spectrum, t, style in zip(spectra, times, ("--", "-")):
        ax.loglog(l, np.maximum(spectrum[1:], 1e-300), style, label="t = %.4g" % t)
    anchor = min(4, l.size)
    level = spectra[-1][anchor]
    if level > 0:
        for slope, name in ((-3.0, "$l^{-3}$"), (-5.0 / 3.0, "$l^{-5/3}$")):
            ax.loglog(l, level * (l / anchor) ** slope, ":", color="gray" if slope < -2 else "k",
                      label=name)
    positive = spectra[:, 1:][spectra[:, 1:] > 0]
    if positive.size:
        ax.set_ylim(max(positive.min(), positive.max() * 1e-14), positive.max() * 10)
    ax.set_xlabel("degree $l$")
    ax.set_ylabel("$E_l$")
    ax.set_title("energy spectrum, N = %d, alpha = %g, %s" % (summary["n"], summary["alpha"],
                                                             summary["method"]))
    ax.grid(alpha=0.3, which="both")
    ax.legend()
    fig.tight_layout()
    save(fig, out, "spectrum.png")


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    out = sys.argv[1]
    with open(os.path.join(out, "summary.json")) as f:
        summary = json.load(f)
    plot_history(out, summary)
    plot_sphere(out, summary)
    plot_spectrum(out, summary)


if __name__ == "__main__":
    main()
