#!/usr/bin/env python3
"""The canonical scale decomposition of a fluid-relax run's final state on the sphere: W, its
part W_s diagonal in the stream matrix's eigenbasis and the rest W_r = W - W_s
(systems/zeitlin_spectra.h), side by side in Mollweide projection, one colour scale.

Usage: PYTHONPATH=build/python plot_scale_decomposition.py OUT_DIR [FIGURE.png]

Reads OUT_DIR's W_final.csv (the relative vorticity W) and summary.json (N, alpha, rotation,
deformation radius); every formula is the library's, through the Python module ddb
(ZeitlinFluid.scale_decomposition, omega_lm, vorticity_on_grid on quflow's grid). Writes
FIGURE.png (default OUT_DIR/scale_decomposition.png).
"""
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import ddb  # noqa: E402


def read_matrix(path):
    """W_final.csv: N rows of Re W[j, :] then Im W[j, :]."""
    values = np.loadtxt(path, delimiter=",", ndmin=2)
    n = values.shape[0]
    return values[:, :n] + 1j * values[:, n:]


def main():
    if len(sys.argv) not in (2, 3):
        sys.exit(__doc__)
    out = sys.argv[1]
    figure = sys.argv[2] if len(sys.argv) == 3 else os.path.join(out, "scale_decomposition.png")
    with open(os.path.join(out, "summary.json")) as f:
        summary = json.load(f)
    W = read_matrix(os.path.join(out, "W_final.csv"))
    n = W.shape[0]
    fluid = ddb.zeitlin(n, summary["alpha"], rotation=summary["rotation"],
                        deformation_radius=summary["deformation_radius"])
    Q = W + fluid.planetary_vorticity()
    steady, remainder = fluid.scale_decomposition(Q)
    theta, phi = ddb.grid_coordinates(n)
    latitude, longitude = np.pi / 2 - theta, np.where(phi > np.pi, phi - 2 * np.pi, phi)
    order = np.argsort(longitude)
    parts = [("W", W), ("$W_s$ (diagonal in $\\psi$'s eigenbasis)", steady),
             ("$W_r = W - W_s$", remainder)]
    fields = [ddb.vorticity_on_grid(fluid.omega_lm(X))[:, order] for _, X in parts]
    limit = max(np.abs(f).max() for f in fields)
    fig = plt.figure(figsize=(15, 4.0), layout="constrained")
    for i, ((name, X), field) in enumerate(zip(parts, fields)):
        ax = fig.add_subplot(1, 3, i + 1, projection="mollweide")
        mesh = ax.pcolormesh(longitude[order], latitude, field, cmap="RdBu_r", vmin=-limit,
                             vmax=limit, shading="auto", rasterized=True)
        ax.set_title("%s, $\\|\\cdot\\|_F$ = %.3g" % (name, np.linalg.norm(X)))
        ax.set_xticklabels([])
        ax.grid(alpha=0.3)
    fig.suptitle("scale decomposition at t = %.4g, N = %d, alpha = %g, rotation %g, %s" %
                 (summary["t_end"], n, summary["alpha"], summary["rotation"], summary["method"]))
    fig.colorbar(mesh, ax=fig.axes, orientation="horizontal", fraction=0.06, shrink=0.4,
                 label="$\\omega$ (one scale for the three)")
    fig.savefig(figure, dpi=110)
    print(figure)


if __name__ == "__main__":
    main()
