"""quflow's magnetic midpoint rule beside ddb-cay on Zeitlin's ideal magnetic fluid (alpha = 0).

At alpha = 0 the DDB Cayley step is the isospectral midpoint rule (docs/reference/conventions.md,
§2), which quflow integrates the magnetic fluid with (quflow/integrators/mhd.py,
magmp_fixedpoint): two codes of one method. This script runs both from the same state and prints

* accuracy (N = 32, t in [0, 1]): both against ddb4-cay at h = 0.0025, with the fitted order of
  each, and their distance from each other at every h;
* cost (N = 64, 128, 256): one step of each at h = c hbar / ||P0||_2 (c = 0.02, the fluid
  benchmarks' step, and 0.2), in complex N x N products (numpy's matmul on the same BLAS, timed
  in the same run), quflow at its own tolerance and at 1e-13 ||W0||_inf, best of three timings.

Needs quflow's source (github.com/klasmodin/quflow; not a dependency of ddb), the Python module
(build/python) and Debian's numba. quflow's spherical transforms need ducc0, which Debian 12 does
not package and which these runs do not call: a placeholder module stands in for it.

  OPENBLAS_NUM_THREADS=1 NUMBA_NUM_THREADS=1 taskset -c 1 /usr/bin/python3 \
      bench/quflow_mhd_midpoint.py --quflow ~/src/quflow --ddb build/python
"""
import argparse
import sys
import time
import types

import numpy as np

parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
parser.add_argument("--quflow", required=True, help="a checkout of klasmodin/quflow")
parser.add_argument("--ddb", default="build/python", help="the folder of the built Python module")
args = parser.parse_args()
sys.modules.setdefault("ducc0", types.ModuleType("ducc0"))
sys.path[:0] = [args.quflow, args.ddb]
import ddb  # noqa: E402
from quflow.geometry import hbar  # noqa: E402
from quflow.integrators import mhd  # noqa: E402
from quflow.laplacian import solve_poisson  # noqa: E402


def initial_state(n):
    """W of degrees 1-6 and Theta of degrees 1-4, as examples/python/mhd.py."""
    fluid = ddb.zeitlin(n, 0.0)
    rng = np.random.default_rng(7)

    def low_modes(l_max, amplitude):
        omega = np.zeros(n * n)
        for l in range(1, l_max + 1):
            for m in range(-l, l + 1):
                omega[l * l + l + m] = rng.normal(0.0, amplitude / l)
        return fluid.vorticity(omega)

    return np.stack([low_modes(6, 1.0), low_modes(4, 0.05)])


def ours(system, method, mu0, h, steps):
    return ddb.integrate(system, method, mu0, h, steps, every=steps)[1][-1]


def quflow(mu0, h, steps, tol="auto", stats=None):
    state = mu0.copy()
    if tol == "auto":
        mhd.magmp_fixedpoint(state, h, steps=steps, stats=stats)
    else:
        mhd.magmp_fixedpoint(state, h, steps=steps, tol=tol, maxit=100, stats=stats)
    return state


def best(job, repeat=3):
    times = []
    for _ in range(repeat):
        start = time.perf_counter()
        job()
        times.append(time.perf_counter() - start)
    return min(times)


# Accuracy.
n, t_end = 32, 1.0
mu0 = initial_state(n)
system = ddb.zeitlin_mhd(n, 0.0)
tight = 1e-13 * np.linalg.norm(mu0[0], np.inf)
reference = ours(system, "ddb4-cay", mu0, 0.0025, 400)
scale = np.linalg.norm(reference)
print(f"N = {n}, t = {t_end}; reference ddb4-cay h = 0.0025, its distance from h = 0.005: "
      f"{np.linalg.norm(reference - ours(system, 'ddb4-cay', mu0, 0.005, 200)) / scale:.1e}")
hs = [0.04, 0.02, 0.01, 0.005]
errors = {"quflow magmp (tol 1e-13)": [], "ddb-cay": [], "sddb-cay": []}
for h in hs:
    steps = int(round(t_end / h))
    q = quflow(mu0, h, steps, tight)
    a, b = ours(system, "ddb-cay", mu0, h, steps), ours(system, "sddb-cay", mu0, h, steps)
    for name, state in zip(errors, (q, a, b)):
        errors[name].append(np.linalg.norm(state - reference) / scale)
    print(f"h = {h}: |quflow - ddb-cay| {np.linalg.norm(q - a) / scale:.1e}, "
          f"|quflow - sddb-cay| {np.linalg.norm(q - b) / scale:.1e}")
for name, e in errors.items():
    slope = np.polyfit(np.log(hs), np.log(e), 1)[0]
    print(f"{name}: errors {' '.join(f'{x:.3e}' for x in e)}, fitted order {slope:.3f}")

# Cost.
for c in (0.02, 0.2):
    for n, steps in ((64, 100), (128, 50), (256, 30)):
        mu0 = initial_state(n)
        system = ddb.zeitlin_mhd(n, 0.0)
        h = c * hbar(N=n) / np.linalg.norm(solve_poisson(mu0[0].copy()), 2)
        tight = 1e-13 * np.linalg.norm(mu0[0], np.inf)
        x, y, z = mu0[0].copy(), mu0[1].copy(), np.empty_like(mu0[0])
        product = best(lambda: [np.matmul(x, y, out=z) for _ in range(20)]) / 20
        ddb_step = best(lambda: ours(system, "ddb-cay", mu0, h, steps)) / steps
        default_stats, tight_stats = {"iterations": 0}, {"iterations": 0}
        q_default = best(lambda: quflow(mu0, h, steps, stats=default_stats)) / steps
        q_tight = best(lambda: quflow(mu0, h, steps, tight, tight_stats)) / steps
        a = ours(system, "ddb-cay", mu0, h, steps)
        distance = [np.linalg.norm(quflow(mu0, h, steps, tol) - a) / np.linalg.norm(a)
                    for tol in ("auto", tight)]
        print(f"c = {c}, N = {n}, h = {h:.3e}, {steps} steps: product {product * 1e3:.3f} ms; "
              f"ddb-cay {ddb_step / product:.1f} products; quflow {q_default / product:.1f} "
              f"({default_stats['iterations']:.2f} iterations, from ddb-cay {distance[0]:.1e}) "
              f"and at 1e-13 {q_tight / product:.1f} ({tight_stats['iterations']:.2f}, "
              f"{distance[1]:.1e}) products per step", flush=True)
