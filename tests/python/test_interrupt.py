"""Ctrl-C during ddb.integrate(): the run stops with KeyboardInterrupt, carrying the states kept
so far. Each case runs in a child interpreter that sends itself SIGINT, so that the signal can
never reach pytest's own process."""
import json
import os
import subprocess
import sys

import numpy as np
import pytest

import ddb

# The child: starts a run of `steps` steps (far longer than the bound below, uninterrupted),
# sends itself SIGINT from a thread once the run has begun, and reports how long the run went
# on after the signal and what the KeyboardInterrupt carried.
CHILD = r"""
import json, os, signal, sys, threading, time
import numpy as np
import ddb

system_kind, method, steps, every = sys.argv[1], sys.argv[2], int(sys.argv[3]), int(sys.argv[4])
a = ddb.scenario("A")
if system_kind == "python":
    system = ddb.user_system("SO3", lambda m: 0.5 * float(np.sum(m * m / a.inertia)),
                             lambda m: m / a.inertia, alpha=a.alpha)
else:
    system = a.system()
sent = []

def interrupt():
    time.sleep(0.3)
    sent.append(time.monotonic())
    os.kill(os.getpid(), signal.SIGINT)

threading.Thread(target=interrupt, daemon=True).start()
try:
    ddb.integrate(system, method, a.mu0, 0.1, steps, every=every)
    print(json.dumps({"interrupted": False}))
except KeyboardInterrupt as e:
    print(json.dumps({"interrupted": True, "after_signal_s": time.monotonic() - sent[0],
                      "times": e.times.tolist(), "states": e.states.tolist()}))
"""


def run_interrupted(system_kind, method, steps, every):
    child = subprocess.run([sys.executable, "-c", CHILD, system_kind, method, str(steps),
                            str(every)], capture_output=True, text=True, timeout=120,
                           env=dict(os.environ, OPENBLAS_NUM_THREADS="1"))
    assert child.returncode == 0, child.stderr
    return json.loads(child.stdout)


@pytest.mark.parametrize("system_kind, method, steps", [
    # About 0.1 us a step: 1e10 steps run for about 1000 s uninterrupted.
    ("library", "ddb-cay", 10**10),
    # A Hamiltonian written in Python, about 7 us a step: 1e9 steps run for about 2 hours.
    ("python", "rk4", 10**9),
])
def test_ctrl_c_stops_integrate_and_keeps_the_states(system_kind, method, steps):
    every = 10**5
    result = run_interrupted(system_kind, method, steps, every)
    assert result["interrupted"]
    # Generous against the machine's load; the run itself checks every 50 ms.
    assert result["after_signal_s"] < 5.0
    times, states = np.array(result["times"]), np.array(result["states"])
    # Every `every`-th state and the last one computed before the interrupt.
    last = round(times[-1] / 0.1)
    assert 0 < last < steps
    kept = list(range(0, last + 1, every)) + ([last] if last % every else [])
    np.testing.assert_allclose(times, 0.1 * np.array(kept), rtol=1e-12)
    if system_kind == "library":
        # The kept states are those of an uninterrupted run of `last` steps, to the bit.
        a = ddb.scenario("A")
        _, expected = ddb.integrate(a.system(), method, a.mu0, 0.1, last, every=every)
        np.testing.assert_array_equal(states, expected)
    assert np.all(np.isfinite(states))
