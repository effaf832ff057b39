#!/usr/bin/env python3
"""What the Python module costs over C++ (docs/results/python-overhead.md, "Speed"); not part
of ctest.

Usage: OPENBLAS_NUM_THREADS=1 PYTHONPATH=BUILD/python python3 bench/python_overhead.py BUILD

In one run:
1. ddb.integrate(rigid body of Scenario A, ddb-cay, h = 0.1, 1e4 steps) against the same run
   in C++ (BUILD/bin/ddb-python-peer: makeMethod + integrate, every state kept), median and
   minimum of 201 runs each, and the cost of a call with 0 steps;
2. the same for the fluid, zeitlin(128, 0.5), ddb-cay, h = 0.01, 20 steps, 11 runs each;
3. a rigid body whose Hamiltonian is written in Python (ddb.user_system) against
   ddb.rigid_body, per step, for ddb-cay (Hamiltonian form on both: the C++ body given
   without its Lagrangian is not available from Python, so the C++ side runs the Lagrangian
   form; see the note printed) and rk4;
4. the fluid's H written in Python around the library's Poisson solve, N = 64, 10 steps,
   against ddb.zeitlin, for ddb-cay and rk4.
"""
import json
import os
import statistics
import subprocess
import sys
import time

import numpy as np

import ddb

REPEATS = 201  # the machine is shared: medians of few ~1 ms runs vary by 10 %
FLUID_REPEATS = 11


def seconds(run, repeats):
    times = []
    for _ in range(repeats):
        start = time.perf_counter()
        run()
        times.append(time.perf_counter() - start)
    return times


def peer(build, *args):
    out = subprocess.run([os.path.join(build, "bin", "ddb-python-peer"), *map(str, args)],
                         check=True, capture_output=True, text=True).stdout
    return json.loads(out)["seconds"]


def compare(build, label, system, method, mu0, h, steps, repeats, n=None):
    """ddb.integrate against the peer on the same system (rigid-body, or zeitlin of size n)."""
    py = seconds(lambda: ddb.integrate(system, method, mu0, h, steps), repeats)
    cpp = peer(build, "rigid-body" if n is None else "zeitlin", method, steps, h, repeats,
               *([] if n is None else [n]))
    for what, f in (("median", statistics.median), ("minimum", min)):
        print(f"{label}, {what} of {repeats}: python {f(py) * 1e3:.4f} ms, C++ "
              f"{f(cpp) * 1e3:.4f} ms, ratio {f(py) / f(cpp):.4f} ({(f(py) / f(cpp) - 1) * 100:+.2f} %)")


def main():
    build = sys.argv[1] if len(sys.argv) > 1 else "build"
    print("OPENBLAS_NUM_THREADS =", os.environ.get("OPENBLAS_NUM_THREADS"))
    a = ddb.scenario("A")
    steps = 10000
    compare(build, f"rigid body ddb-cay, {steps} steps", a.system(), "ddb-cay", a.mu0, 0.1, steps,
            REPEATS)
    body = a.system()
    call = statistics.median(seconds(lambda: ddb.integrate(body, "ddb-cay", a.mu0, 0.1, 0), REPEATS))
    print(f"a call with 0 steps (system built outside): {call * 1e6:.2f} us")
    n, fluid_steps = 128, 20
    compare(build, f"fluid N = {n} ddb-cay, {fluid_steps} steps", ddb.zeitlin(n, 0.5), "ddb-cay",
            ddb.zeitlin_vorticity("random", n, 1), 0.01, fluid_steps, FLUID_REPEATS, n)

    inertia = np.asarray(a.inertia)
    calls = [0]

    def gradient(m):
        calls[0] += 1
        return m / inertia

    def hessian_times(m, v):
        calls[0] += 1
        return v / inertia

    user = ddb.user_system("SO3", lambda m: 0.5 * float(np.sum(m * m / inertia)), gradient,
                           hessian_times, alpha=a.alpha)
    user_steps = 2000
    for method in ("ddb-cay", "rk4"):
        calls[0] = 0
        ddb.integrate(user, method, a.mu0, 0.1, user_steps)
        run_calls = calls[0]
        py = statistics.median(
            seconds(lambda: ddb.integrate(user, method, a.mu0, 0.1, user_steps), 5))
        cpp = statistics.median(
            seconds(lambda: ddb.integrate(body, method, a.mu0, 0.1, user_steps), 5))
        print(f"Python-defined rigid body, {method}: {py / user_steps * 1e6:.2f} us/step "
              f"({run_calls / user_steps:.2f} Python calls/step, {py / run_calls * 1e6:.2f} "
              f"us/call) "
              f"against {cpp / user_steps * 1e6:.3f} us/step for ddb.rigid_body (x{py / cpp:.0f})")
    print("note: ddb.rigid_body has a Lagrangian, so its ddb-cay runs the Lagrangian form; the "
          "Python body has none and runs the Hamiltonian form")

    # The fluid's H written in Python around the library's Poisson solve (stream_matrix):
    # what the calls cost where each one does O(N^2) work.
    n, fluid_steps = 64, 10
    fluid = ddb.zeitlin(n, 0.5)
    hbar = fluid.hbar
    python_fluid = ddb.user_system(
        "SU(N)", lambda W: float(np.real(np.trace(W @ fluid.stream_matrix(W)))) / (2 * hbar),
        lambda W: -fluid.stream_matrix(W) / hbar, lambda W, V: -fluid.stream_matrix(V) / hbar,
        alpha=0.5, N=n)
    W0 = ddb.zeitlin_vorticity("random", n, 1)
    for method in ("ddb-cay", "rk4"):
        py = statistics.median(
            seconds(lambda: ddb.integrate(python_fluid, method, W0, 0.01, fluid_steps), 5))
        cpp = statistics.median(
            seconds(lambda: ddb.integrate(fluid, method, W0, 0.01, fluid_steps), 5))
        print(f"Python-defined fluid N = {n}, {method}: {py / fluid_steps * 1e3:.3f} ms/step "
              f"against {cpp / fluid_steps * 1e3:.3f} ms/step for ddb.zeitlin (x{py / cpp:.2f})")


if __name__ == "__main__":
    main()
