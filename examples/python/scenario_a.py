"""The paper's Scenario A from Python: the DDB methods keep the Casimir |M| to round-off while
the energy decays; RK4 and Lobatto IIIC drift off the orbit. Writes scenario_a_casimir.png."""
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import ddb  # noqa: E402

a = ddb.scenario("A")  # rigid body I = (1, 1.3, 0.5), alpha = 0.5, M0 = I Omega0, t in [0, 30]
system, h = a.system(), 0.1
fig, ax = plt.subplots(figsize=(8, 4.5))
for method in ["ddb-cay", "sddb-exp", "ddb4-cay", "ddb6-exp", "rk4", "lobatto3c"]:
    t, m = ddb.integrate(system, method, a.mu0, h, round(a.t_end / h))
    c = system.casimirs(m)[:, 0]  # |M|
    e = system.energy(m)
    ax.semilogy(t, np.maximum(np.abs(c / c[0] - 1), 1e-17),
                label=f"{method}: H {e[0]:.4f} -> {e[-1]:.4f}")
ax.set(xlabel="t", ylabel="| |M(t)|/|M(0)| - 1 |  (0 shown at 1e-17)",
       title=f"Scenario A: Casimir drift, h = {h}")
ax.legend(fontsize=8, loc="center right")
fig.tight_layout()
fig.savefig(sys.argv[1] if len(sys.argv) > 1 else "scenario_a_casimir.png", dpi=110)
