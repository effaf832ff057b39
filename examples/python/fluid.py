"""A fluid relaxation from Python: Zeitlin's SU(N) fluid with double-bracket dissipation
(alpha > 0) from a random vorticity towards a steady flow, integrated by DDB (Cayley), which
keeps the spectrum of W (the Casimirs) while the energy falls. Writes fluid.png: the
vorticity on the sphere at t = 0 and t_end (from omega_lm, evaluated by
scripts/plot_fluid.py's vorticity()), and E, ||[P, W]|| and the spectrum drift against t."""
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..",
                                "scripts"))
from plot_fluid import vorticity  # noqa: E402  (first: it selects matplotlib's Agg backend)
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import ddb  # noqa: E402

N, alpha, h, steps = 32, 0.5, 0.05, 400
fluid = ddb.zeitlin(N, alpha)
W0 = ddb.zeitlin_vorticity("random", N, seed=1)
t, W = ddb.integrate(fluid, "ddb-cay", W0, h, steps, every=10)

spectrum = fluid.casimirs(W)
drift = np.abs(spectrum - spectrum[0]).max(axis=1) / np.abs(spectrum[0]).max()
latitude = np.linspace(-math.pi / 2, math.pi / 2, 181)
longitude = np.linspace(-math.pi, math.pi, 361)


def sphere(w):
    coefficients = fluid.omega_lm(w)
    omega = {(l, m): coefficients[l * l + l + m] for l in range(N) for m in range(-l, l + 1)}
    return vorticity(omega, math.pi / 2 - latitude, longitude, N - 1)


fields = [sphere(W[0]), sphere(W[-1])]
limit = max(np.abs(f).max() for f in fields)
fig = plt.figure(figsize=(13, 7.5), layout="constrained")
for i, (field, when) in enumerate(zip(fields, (t[0], t[-1]))):
    ax = fig.add_subplot(2, 2, i + 1, projection="mollweide")
    mesh = ax.pcolormesh(longitude, latitude, field, cmap="RdBu_r", vmin=-limit, vmax=limit,
                         shading="auto", rasterized=True)
    ax.set_title(f"vorticity, t = {when:g}")
    ax.set_xticklabels([])
fig.colorbar(mesh, ax=fig.axes[:2], orientation="vertical", shrink=0.7)
ax = fig.add_subplot(2, 2, 3)
ax.plot(t, fluid.fluid_energy(W) / fluid.fluid_energy(W0), label="E / E(0)")
ax.plot(t, fluid.commutator_norm(W) / fluid.commutator_norm(W0), label="||[P, W]|| / initial")
ax.set(xlabel="t", yscale="log", title="energy falls, the flow steadies")
ax.legend()
ax = fig.add_subplot(2, 2, 4)
ax.semilogy(t[1:], np.maximum(drift[1:], 1e-17))
ax.set(xlabel="t", ylabel="max |spectrum drift| / |W|_2", title="Casimirs: the spectrum of W")
fig.suptitle(f"Zeitlin fluid N = {N}, alpha = {alpha}, ddb-cay, h = {h}")
fig.savefig(sys.argv[1] if len(sys.argv) > 1 else "fluid.png", dpi=100)
