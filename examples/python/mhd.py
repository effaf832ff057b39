"""Magnetohydrodynamics on the sphere from Python: Zeitlin's magnetic fluid (vorticity W, magnetic
potential Theta) relaxed by the double bracket (alpha > 0) towards a magnetic equilibrium,
integrated by DDB (Cayley), which keeps every tr Theta^k and tr(W Theta^k) while the total energy
falls. Writes mhd.png: W and Theta on the sphere at t = 0 and t_end (from omega_lm, evaluated by
scripts/plot_fluid.py's vorticity()), the energies and the equilibrium residual against t, and
the drift of the invariants."""
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..",
                                "scripts"))
from plot_fluid import vorticity  # noqa: E402  (first: it selects matplotlib's Agg backend)
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import ddb  # noqa: E402

N, alpha, h, steps, every = 32, 0.03, 0.01, 20000, 50
mhd = ddb.zeitlin_mhd(N, alpha)
fluid = ddb.zeitlin(N, 0.0)  # its vorticity(omega) makes the matrices of the initial fields
rng = np.random.default_rng(7)


def low_modes(l_max, amplitude):
    """sum omega_lm T_lm over 1 <= l <= l_max, omega_lm normal with deviation amplitude / l."""
    omega = np.zeros(N * N)
    for l in range(1, l_max + 1):
        for m in range(-l, l + 1):
            omega[l * l + l + m] = rng.normal(0.0, amplitude / l)
    return fluid.vorticity(omega)


# The magnetic energy a quarter of the kinetic. h is within the double bracket's stability bound
# on the magnetic part, which falls as alpha ||Theta||^2 N^2 / hbar grows (at alpha = 0.1 this
# h lets the energy rise; docs/guide/matrix-groups-and-the-fluid.md).
mu0 = np.stack([low_modes(6, 1.0), low_modes(4, 0.05)])
t, states = ddb.integrate(mhd, "ddb-cay", mu0, h, steps, every=every)

kinetic, magnetic = mhd.kinetic_energy(states), mhd.magnetic_energy(states)
assert np.all(np.diff(kinetic + magnetic) <= 0), "the total energy must not rise"
# tr Theta^k and tr(W Theta^k), k = 1..4, over their scales N ||Theta||^k and N ||W|| ||Theta||^k.
theta_norm, w_norm = np.linalg.norm(mu0[1], 2), np.linalg.norm(mu0[0], 2)
invariants = []
for k in range(1, 5):
    powers = [np.linalg.matrix_power(s[1], k) for s in states]
    pure = np.array([np.trace(p) for p in powers])
    mixed = np.array([np.trace(s[0] @ p) for s, p in zip(states, powers)])
    invariants.append(np.abs(pure - pure[0]) / (N * theta_norm**k))
    invariants.append(np.abs(mixed - mixed[0]) / (N * w_norm * theta_norm**k))
drift = np.max(invariants, axis=0)
latitude = np.linspace(-math.pi / 2, math.pi / 2, 181)
longitude = np.linspace(-math.pi, math.pi, 361)


def sphere(coefficients):
    omega = {(l, m): coefficients[l * l + l + m] for l in range(N) for m in range(-l, l + 1)}
    return vorticity(omega, math.pi / 2 - latitude, longitude, N - 1)


fig = plt.figure(figsize=(13, 11), layout="constrained")
for row, (part, name) in enumerate(((0, "vorticity W"), (1, "magnetic potential Theta"))):
    fields = [sphere(mhd.omega_lm(states[i])[part]) for i in (0, -1)]
    limit = max(np.abs(f).max() for f in fields)
    for col, (field, when) in enumerate(zip(fields, (t[0], t[-1]))):
        ax = fig.add_subplot(3, 2, 2 * row + col + 1, projection="mollweide")
        mesh = ax.pcolormesh(longitude, latitude, field, cmap="RdBu_r", vmin=-limit, vmax=limit,
                             shading="auto", rasterized=True)
        ax.set_title(f"{name}, t = {when:g}")
        ax.set_xticklabels([])
    fig.colorbar(mesh, ax=fig.axes[-2:], orientation="vertical", shrink=0.7)
ax = fig.add_subplot(3, 2, 5)
ax.plot(t, kinetic, label="E_kin")
ax.plot(t, magnetic, label="E_mag")
ax.plot(t, kinetic + magnetic, label="E_kin + E_mag")
ax2 = ax.twinx()
ax2.semilogy(t, mhd.residual(states), color="k", ls=":", label="residual")
ax2.set_ylabel("||([P, Theta], [P, W] + [B, Theta])||")
ax.set(xlabel="t", ylabel="energy", title="energy falls to a magnetic equilibrium")
ax.legend(loc="center right")
ax = fig.add_subplot(3, 2, 6)
ax.semilogy(t[1:], np.maximum(drift[1:], 1e-17))
ax.set(xlabel="t", ylabel="max relative drift",
       title="Casimirs tr Theta^k, tr(W Theta^k), k <= 4")
fig.suptitle(f"Magnetohydrodynamics on the sphere, N = {N}, alpha = {alpha}, ddb-cay, h = {h}")
fig.savefig(sys.argv[1] if len(sys.argv) > 1 else "mhd.png", dpi=100)
print(f"E: {kinetic[0] + magnetic[0]:.6g} -> {kinetic[-1] + magnetic[-1]:.6g}; residual "
      f"{mhd.residual(states[0]):.3g} -> {mhd.residual(states[-1]):.3g}; "
      f"largest invariant drift {drift.max():.2g}")
