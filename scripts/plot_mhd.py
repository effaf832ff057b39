#!/usr/bin/env python3
"""The figure of an mhd-relax output folder (docs/reference/command-lines-and-files.md,
"mhd-relax"), from its fluid.hdf5 and history.csv.

Usage: plot_mhd.py OUT_DIR

mhd.png  the vorticity W and the magnetic potential Theta on the sphere at the first and last
         rows (Mollweide, one colour scale per field; plot_fluid.py's vorticity() of the
         coefficients omega_lm the file holds), the kinetic, magnetic and total energy and the
         equilibrium residual against t, and the drift of the invariants tr Theta^k and
         tr(W Theta^k) (history.csv's invariant_drift, zeros omitted).
"""
import math
import os
import sys

from plot_fluid import L_MAX_PLOTTED, read_columns, save, vorticity  # selects Agg first
import h5py  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def main(out):
    with h5py.File(os.path.join(out, "fluid.hdf5"), "r") as f:
        n = int(f.attrs["N"])
        time = f["time"][:]
        fields = {"vorticity W": f["state"][[0, -1]], "magnetic potential Theta":
                  f["theta/state"][[0, -1]]}
        method, alpha = f.attrs["method"], float(f.attrs["alpha"])
    history = read_columns(os.path.join(out, "history.csv"))
    l_max = min(n - 1, L_MAX_PLOTTED)
    latitude = np.linspace(-math.pi / 2, math.pi / 2, 121)
    longitude = np.linspace(-math.pi, math.pi, 241)

    def sphere(coefficients):
        omega = {(l, m): coefficients[l * l + l + m] for l in range(l_max + 1)
                 for m in range(-l, l + 1)}
        return vorticity(omega, math.pi / 2 - latitude, longitude, l_max)

    fig = plt.figure(figsize=(13, 11), layout="constrained")
    for row, (name, frames) in enumerate(fields.items()):
        values = [sphere(frames[i]) for i in (0, 1)]
        limit = max(np.abs(v).max() for v in values) or 1.0
        for col, (value, t) in enumerate(zip(values, (time[0], time[-1]))):
            ax = fig.add_subplot(3, 2, 2 * row + col + 1, projection="mollweide")
            mesh = ax.pcolormesh(longitude, latitude, value, cmap="RdBu_r", vmin=-limit,
                                 vmax=limit, shading="auto", rasterized=True)
            ax.set_title(f"{name}, t = {t:g}")
            ax.set_xticklabels([])
        fig.colorbar(mesh, ax=fig.axes[-2:], orientation="vertical", shrink=0.7)
    t = history["t"]
    ax = fig.add_subplot(3, 2, 5)
    ax.plot(t, history["kinetic_energy"], label="E_kin")
    ax.plot(t, history["magnetic_energy"], label="E_mag")
    ax.plot(t, history["energy"], label="E_kin + E_mag")
    ax.set(xlabel="t", ylabel="energy", title="energies")
    ax.legend(loc="center right")
    ax2 = ax.twinx()
    ax2.semilogy(t, history["equilibrium_residual"], color="k", ls=":")
    ax2.set_ylabel("||([P, Theta], [P, W] + [B, Theta])||_F (dotted)")
    ax = fig.add_subplot(3, 2, 6)
    drift = history["invariant_drift"]
    kept = drift > 0
    ax.semilogy(t[kept], drift[kept], ".-")
    ax.set(xlabel="t", ylabel="largest relative drift",
           title="tr Theta^k (k = 2..4), tr(W Theta^k) (k = 1..3)")
    truncated = f" (l <= {l_max} drawn)" if l_max < n - 1 else ""
    fig.suptitle(f"mhd-relax: N = {n}, alpha = {alpha:g}, {method}{truncated}")
    save(fig, out, "mhd.png")


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit("usage: plot_mhd.py OUT_DIR")
    main(sys.argv[1])
