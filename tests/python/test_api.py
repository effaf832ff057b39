"""The module's contract: Casimirs against independent formulas, the method table, `every`,
failed solves as ddb.SolveFailure with the valid prefix, and bad arguments as ValueError."""
import ctypes
import os
import re
import subprocess
import sys
import threading
import time

import numpy as np
import pytest

import ddb


def test_methods_are_the_table():
    rows = ddb.methods()
    names = [r["name"] for r in rows]
    assert names[0] == "ddb-cay" and "reference" in names and len(set(names)) == len(names)
    for r in rows:
        assert r["description"] and r["groups"]
    assert set(ddb.rigid_body().methods()) == set(names)
    assert "sddb-paper-cay" not in ddb.heavy_top().methods()
    matrix = [r["name"] for r in rows if "SU(N)" in r["groups"]]
    assert ddb.zeitlin(4, 0.5).methods() == matrix
    magnetic = [r["name"] for r in rows if "SU(N) x| su(N)*" in r["groups"]]
    assert ddb.zeitlin_mhd(4, 0.5).methods() == magnetic


@pytest.mark.parametrize("method", ["ddb-cay", "sddb-exp", "ddb4-cay", "ddb6-exp"])
def test_rigid_body_keeps_the_norm_and_loses_energy(method):
    a = ddb.scenario("A")
    system = a.system()
    t, m = ddb.integrate(system, method, a.mu0, 0.1, 300)
    assert t.shape == (301,) and m.shape == (301, 3) and t[-1] == pytest.approx(30.0)
    norm = np.linalg.norm(m, axis=1)  # |m|, not the library's casimirs()
    # Round-off of up to 7 * 300 sub-steps (ddb6-exp); rk4 below drifts by more than 1e-9.
    assert np.max(np.abs(norm / norm[0] - 1)) < 1e-13
    np.testing.assert_allclose(system.casimirs(m)[:, 0], norm, rtol=1e-15)
    energy = system.energy(m)
    assert energy.shape == (301,)
    assert energy[-1] < 0.9 * energy[0]
    assert np.all(np.diff(energy) <= 1e-15 * energy[0])
    # H = m.I^-1 m / 2, written out here.
    np.testing.assert_allclose(energy, 0.5 * (m**2 / a.inertia).sum(axis=1), rtol=1e-15)


def test_rk4_drifts_off_the_orbit():
    a = ddb.scenario("A")
    _, m = ddb.integrate(a.system(), "rk4", a.mu0, 0.3, 100)
    norm = np.linalg.norm(m, axis=1)
    assert np.max(np.abs(norm / norm[0] - 1)) > 1e-9


def spectrum(W):
    return np.sort(np.linalg.eigvals(-1j * W).real)  # numpy's eigensolver, not the library's


def test_fluid_keeps_its_spectrum():
    fluid = ddb.zeitlin(8, 0.5)
    W0 = ddb.zeitlin_vorticity("random", 8, 5)
    assert W0.shape == (8, 8) and W0.dtype == np.complex128
    np.testing.assert_allclose(W0, -W0.conj().T, atol=1e-15)
    t, W = ddb.integrate(fluid, "sddb-cay", W0, 0.05, 60, every=10)
    assert W.shape == (7, 8, 8) and t[-1] == pytest.approx(3.0)
    drift = max(np.max(np.abs(spectrum(w) - spectrum(W0))) for w in W)
    assert drift < 1e-12 * np.max(np.abs(spectrum(W0)))
    np.testing.assert_allclose(fluid.casimirs(W), [spectrum(w) for w in W], atol=1e-13)
    energy = fluid.fluid_energy(W)
    assert np.all(np.diff(energy) < 0)
    # E = hbar H / N and Z = |W|^2/(2N), from their definitions.
    np.testing.assert_allclose(energy, fluid.hbar * fluid.energy(W) / 8, rtol=1e-14)
    np.testing.assert_allclose(fluid.enstrophy(W),
                               [np.linalg.norm(w)**2 / 16 for w in W], rtol=1e-14)
    P = fluid.stream_matrix(W[-1])
    assert fluid.commutator_norm(W[-1]) == pytest.approx(np.linalg.norm(P @ W[-1] - W[-1] @ P),
                                                         rel=1e-12)
    assert fluid.commutator_norm(W[-1]) < fluid.commutator_norm(W0)


def test_omega_lm_round_trip_and_the_initial_vorticities():
    fluid = ddb.zeitlin(6, 0.0)
    W = ddb.zeitlin_vorticity("random", 6, 2)
    omega = fluid.omega_lm(W)
    assert omega.shape == (36,)
    np.testing.assert_allclose(fluid.vorticity(omega), W, atol=1e-13)
    # Parseval for the basis orthonormal under Re tr(A^H B)/N.
    assert np.sum(omega**2) == pytest.approx(np.linalg.norm(W)**2 / 6, rel=1e-13)
    # l1: U X3 U^H keeps the spectrum of X3 = hbar i diag(j - (N-1)/2), normalised.
    x3 = np.arange(6) - 2.5
    np.testing.assert_allclose(spectrum(ddb.zeitlin_vorticity("l1", 6, 4)),
                               x3 * np.sqrt(6) / np.linalg.norm(x3), atol=1e-13)
    # zonal: i diag(d), a steady state.
    zonal = ddb.zeitlin_vorticity("zonal", 6, 4)
    np.testing.assert_array_equal(zonal, np.diag(np.diag(zonal)))
    assert fluid.commutator_norm(zonal) < 1e-14


def test_rotating_sphere_planetary_vorticity_and_the_rossby_haurwitz_drift():
    n, omega_rate, kappa2 = 8, 1.5, 2.0
    fluid = ddb.zeitlin(n, 0.0, rotation=omega_rate, deformation_radius=1 / np.sqrt(kappa2))
    # F = 2 Omega cos(theta) = (2 Omega / sqrt 3) Y_10, built from the basis's coefficients.
    coefficients = np.zeros(n * n)
    coefficients[1 * 1 + 1 + 0] = 2 * omega_rate / np.sqrt(3)
    F = fluid.planetary_vorticity()
    np.testing.assert_allclose(F, fluid.vorticity(coefficients), atol=1e-13)
    np.testing.assert_array_equal(ddb.zeitlin(n, 0.0).planetary_vorticity(), np.zeros((n, n)))
    # A Rossby-Haurwitz wave (l, m) = (3, 2): Q(t) - F = U W U^H, U = diag(exp(i j c t)),
    # c = 2 Omega / (l(l+1) + kappa^2); rk4 at a small step against that closed form.
    coefficients = np.zeros(n * n)
    coefficients[3 * 3 + 3 + 2] = 1.0
    W = fluid.vorticity(coefficients)
    c, h, steps = 2 * omega_rate / (12 + kappa2), 0.01, 200
    _, states = ddb.integrate(fluid, "rk4", W + F, h, steps)
    Q = states[-1]
    u = np.exp(1j * np.arange(n) * c * h * steps)
    exact = (u[:, None] * W) * u.conj()[None, :]
    np.testing.assert_allclose(Q - F, exact, atol=1e-10)


def test_damping_and_forcing_are_exact_flows_split_around_the_method():
    # Zonal flows (diagonal W) are steady on a resting or rotating sphere ([P, W] = 0, and the
    # double bracket vanishes with it): what moves them is the damping's and the forcing's
    # exact flows alone, whose closed forms are written here.
    n, h, steps = 8, 0.02, 50
    t = h * steps
    W0 = ddb.zeitlin_vorticity("zonal", n, 2)
    # Drag on a rotating sphere: W(t) = exp(-gamma t) W0, W = Q - F.
    fluid = ddb.zeitlin(n, 0.5, rotation=1.0, drag=0.3)
    F = fluid.planetary_vorticity()
    _, states = ddb.integrate(fluid, "sddb-cay", W0 + F, h, steps)
    np.testing.assert_allclose(states[-1] - F, np.exp(-0.3 * t) * W0, atol=1e-12)
    # Hyperviscosity p = 2 on T_30: exp(-nu (l(l + 1))^p t) with l(l + 1) = 12.
    fluid = ddb.zeitlin(n, 0.0, viscosity=1e-3, hyperviscosity_order=2)
    coefficients = np.zeros(n * n)
    coefficients[3 * 3 + 3 + 0] = 1.0
    W = fluid.vorticity(coefficients)
    _, states = ddb.integrate(fluid, "rk4", W, h, steps)
    np.testing.assert_allclose(states[-1], np.exp(-1e-3 * 144 * t) * W, atol=1e-12)
    # The implicit scheme: each half step's factor 1/(1 + z + z^2/2), z = (h/2) nu 144.
    fluid = ddb.zeitlin(n, 0.0, viscosity=1e-3, hyperviscosity_order=2, viscous_scheme="implicit")
    _, states = ddb.integrate(fluid, "rk4", W, h, steps)
    z = 0.5 * h * 1e-3 * 144
    np.testing.assert_allclose(states[-1], (1 + z + z * z / 2) ** (-2 * steps) * W, atol=1e-12)
    # A fixed forcing Phi of a zonal flow: W0 + t Phi.
    phi = 0.3 * fluid.vorticity(np.eye(1, n * n, 1 * 1 + 1 + 0)[0])
    fluid = ddb.zeitlin(n, 0.5, forcing=phi)
    _, states = ddb.integrate(fluid, "sddb-cay", W0, h, steps)
    np.testing.assert_allclose(states[-1], W0 + t * phi, atol=1e-12)
    # Stochastic forcing: the same seed gives the same bits, another seed another run.
    W1 = ddb.zeitlin_vorticity("random", n, 5)

    def forced(seed):
        fluid = ddb.zeitlin(n, 0.5, forcing_band=(3, 1), forcing_rate=1e-2, forcing_seed=seed)
        return ddb.integrate(fluid, "ddb-cay", W1, h, 20)[1][-1]

    np.testing.assert_array_equal(forced(3), forced(3))
    assert np.linalg.norm(forced(3) - forced(4)) > 1e-6


def test_field_diagnostics_sum_to_the_energy_and_enstrophy():
    n = 9
    fluid = ddb.zeitlin(n, 0.0, rotation=1.0, deformation_radius=0.5)
    W = ddb.zeitlin_vorticity("random", n, 3)
    Q = W + fluid.planetary_vorticity()
    E, Z = fluid.energy_spectrum(Q), fluid.enstrophy_spectrum(Q)
    assert E.shape == (n,) and Z.shape == (n,)
    assert E.sum() == pytest.approx(fluid.fluid_energy(Q), rel=1e-12)
    assert Z.sum() == pytest.approx(fluid.enstrophy(Q), rel=1e-12)
    # gamma from the coefficients written out here: the l = 1 ones are at indices 1, 2, 3.
    omega = fluid.omega_lm(W)
    assert fluid.gamma(Q) == pytest.approx(np.linalg.norm(omega[1:4]) / np.linalg.norm(omega),
                                           rel=1e-12)
    Ws, Wr = fluid.scale_decomposition(Q)
    np.testing.assert_allclose(Ws + Wr, W, atol=1e-13)
    P = fluid.stream_matrix(Q)
    assert np.linalg.norm(Ws @ P - P @ Ws) < 1e-12 * np.linalg.norm(Ws) * np.linalg.norm(P)


def test_vorticity_on_the_grid():
    # F = 2 Omega X3 quantises 2 Omega cos(theta): the quantisation's scale, sqrt(4 pi).
    n, rotation = 7, 1.3
    fluid = ddb.zeitlin(n, 0.0, rotation=rotation)
    theta, phi = ddb.grid_coordinates(n)
    assert theta.shape == (n,) and phi.shape == (2 * n - 1,)
    np.testing.assert_allclose(theta, np.pi * (2 * np.arange(n) + 1) / (2 * n - 1), rtol=1e-15)
    F = fluid.planetary_vorticity()
    f = ddb.vorticity_on_grid(fluid.omega_lm(F))
    np.testing.assert_allclose(f, np.outer(2 * rotation * np.cos(theta), np.ones(phi.size)),
                               rtol=0, atol=1e-13)
    # The fluid's grid is of W = Q - F; T_11's is sqrt(4 pi) sqrt(3/(4 pi)) sin(theta) cos(phi).
    coefficients = np.zeros(n * n)
    coefficients[1 + 1 + 1] = 1.0
    W = fluid.vorticity(coefficients)
    np.testing.assert_allclose(fluid.vorticity_on_grid(W + F),
                               np.sqrt(3) * np.outer(np.sin(theta), np.cos(phi)), rtol=0,
                               atol=1e-13)
    with pytest.raises(ValueError, match="omega"):
        ddb.vorticity_on_grid(np.zeros(10))
    with pytest.raises(ValueError, match="omega"):
        ddb.vorticity_on_grid(np.full(9, np.nan))


def test_manakov_and_se3_casimirs():
    rng = np.random.default_rng(1)
    a = rng.standard_normal((5, 5))
    m0 = a - a.T
    system = ddb.manakov([1, 1.2, 1.5, 1.8, 2], 0.5)
    _, M = ddb.integrate(system, "ddb-exp-exact", m0, 0.05, 40)
    assert M.dtype == np.float64 and M.shape == (41, 5, 5)
    for m in M:
        np.testing.assert_allclose(spectrum(m), spectrum(m0), atol=1e-13)
    top = ddb.heavy_top()
    _, mu = ddb.integrate(top, "sddb-cay", ddb.HeavyTopSetup().mu0, 0.1, 50)
    gamma2, pi_gamma = (mu[:, 3:]**2).sum(axis=1), (mu[:, :3] * mu[:, 3:]).sum(axis=1)
    np.testing.assert_allclose(gamma2, gamma2[0], rtol=1e-14)
    np.testing.assert_allclose(pi_gamma, pi_gamma[0], atol=1e-14)
    np.testing.assert_allclose(top.casimirs(mu), np.stack([gamma2, pi_gamma], axis=1),
                               atol=1e-14)


def test_every_keeps_every_kth_and_the_last_state():
    a = ddb.scenario("A")
    t_all, m_all = ddb.integrate(a.system(), "ddb-cay", a.mu0, 0.1, 30)
    t, m = ddb.integrate(a.system(), "ddb-cay", a.mu0, 0.1, 30, every=7)
    kept = [0, 7, 14, 21, 28, 30]
    np.testing.assert_array_equal(t, t_all[kept])
    np.testing.assert_array_equal(m, m_all[kept])


def test_a_failed_solve_is_a_solve_failure_with_its_fields():
    a = ddb.scenario("A")
    with pytest.raises(ddb.SolveFailure) as caught:
        ddb.integrate(a.system(), "ddb-cay", 1e3 * a.mu0, 0.5, 10)  # far too large a step
    e = caught.value
    assert isinstance(e, RuntimeError)
    assert (e.kind, e.step, e.t, e.h) == ("SolveFailure", 0, 0.0, 0.5)
    assert e.residual > e.tolerance > 0
    assert str(e).startswith("discrete Legendre equation did not converge at step 0")
    np.testing.assert_array_equal(e.states, [1e3 * a.mu0])


def test_a_failed_step_keeps_the_states_before_it():
    # alpha < 0 drives the body from its slow axis (I = 1.3) to its fast one (I = 0.5): |xi|
    # grows until |h xi| passes pi, where an exp step would land on another branch.
    system, mu0, h = ddb.rigid_body([1, 1.3, 0.5], -0.5), [0.05, 1.0, 0.05], 2.0
    with pytest.raises(ddb.SolveFailure) as caught:
        ddb.integrate(system, "ddb-exp-exact", mu0, h, 1000, every=3)
    e = caught.value
    assert e.kind == "InjectivityLimit" and e.step > 3
    assert e.t == e.step * h and e.h == h and f"step {e.step} " in str(e)
    _, before = ddb.integrate(system, "ddb-exp-exact", mu0, h, e.step)
    # |h xi| at the failing step's state, from xi = I^-1 m (written out here).
    assert h * np.linalg.norm(before[-1] / [1, 1.3, 0.5]) >= np.pi
    # Every third state and the last one computed.
    kept = list(range(0, e.step + 1, 3)) + ([e.step] if e.step % 3 else [])
    np.testing.assert_array_equal(e.states, before[kept])
    np.testing.assert_array_equal(e.times, h * np.array(kept))


@pytest.mark.parametrize("kwargs, parameter", [
    (dict(h=-0.1), "h = -0.1"),
    (dict(h=float("nan")), "h = nan"),
    (dict(steps=-1), "steps = -1"),
    (dict(every=0), "every = 0"),
    (dict(method="ddb-fast"), "method = ddb-fast"),
    (dict(mu0=[1.0, 2.0]), "mu0 = an array of shape (2,)"),
    (dict(mu0=[1.0, float("nan"), 0.0]), "mu0 = (1, nan, 0)"),
    (dict(mu0=[1j, 0, 0]), "mu0 = an array of dtype complex128"),
    (dict(mu0="abc"), "mu0"),
    (dict(system=None), "system = None"),
    (dict(method=3), "method = 3"),
    (dict(h="0.1"), "h = '0.1'"),
    (dict(steps=1.5), "steps = 1.5"),
    (dict(steps=10**30), "steps = " + str(10**30)),
    (dict(every=2.0), "every = 2.0"),
])
def test_bad_arguments_name_the_parameter(kwargs, parameter):
    a = ddb.scenario("A")
    args = dict(system=a.system(), method="ddb-cay", mu0=a.mu0, h=0.1, steps=10)
    args.update(kwargs)
    with pytest.raises(ValueError) as caught:
        ddb.integrate(**args)
    assert str(caught.value).startswith(parameter)


def test_bad_system_arguments_name_the_parameter():
    cases = [
        (lambda: ddb.rigid_body([1, 2], 0.5), "inertia"),
        (lambda: ddb.rigid_body([1, -2, 3], 0.5), "inertia"),
        (lambda: ddb.rigid_body([1, 2, 3], float("inf")), "alpha"),
        (lambda: ddb.manakov([1, 0, 2], 0.5), "J"),
        (lambda: ddb.zeitlin(1, 0.5), "N = 1"),
        (lambda: ddb.zeitlin_vorticity("vortex", 4), "kind = vortex"),
        (lambda: ddb.scenario("D"), "name = D"),
        (lambda: ddb.scenario(1), "name = 1"),
        # N x N matrices from a user-given N: refused past the documented N <= 4096 before
        # they are allocated (a MemoryError otherwise).
        (lambda: ddb.manakov(np.ones(100_000), 0.5), "J = an array of 100000 numbers"),
        (lambda: ddb.zeitlin(100_000, 0.5), "N = 100000"),
        (lambda: ddb.zeitlin(8.0, 0.5), "N = 8.0"),
        (lambda: ddb.zeitlin(8, 0.5, rotation=float("nan")), "rotation = nan"),
        (lambda: ddb.zeitlin(8, 0.5, deformation_radius=-1.0), "deformation_radius = -1"),
        (lambda: ddb.zeitlin(8, 0.5, deformation_radius="1"), "deformation_radius = '1'"),
        (lambda: ddb.zeitlin(8, 0.5, viscosity=-1.0), "viscosity = -1"),
        (lambda: ddb.zeitlin(8, 0.5, drag=float("inf")), "drag = inf"),
        (lambda: ddb.zeitlin(8, 0.5, hyperviscosity_order=0), "hyperviscosity_order = 0"),
        (lambda: ddb.zeitlin(8, 0.5, hyperviscosity_order=2.0), "hyperviscosity_order = 2.0"),
        (lambda: ddb.zeitlin(8, 0.5, forcing_rate=1e-3), "forcing_rate = 0.001"),
        (lambda: ddb.zeitlin(8, 0.5, forcing_band=(3, 1)), "forcing_band = (3, 1)"),
        (lambda: ddb.zeitlin(8, 0.5, forcing_band=(7, 1), forcing_rate=1e-3),
         "forcing_band = (7, 1)"),
        (lambda: ddb.zeitlin(8, 0.5, forcing_band=(3.5, 1), forcing_rate=1e-3),
         "forcing_band = (3.5, 1)"),
        (lambda: ddb.zeitlin(8, 0.5, forcing_band=(3, 1), forcing_rate=-1.0), "forcing_rate = -1"),
        (lambda: ddb.zeitlin(8, 0.5, forcing=np.eye(8)), "forcing"),
        (lambda: ddb.zeitlin(8, 0.5, viscous_scheme="crank"), "viscous_scheme = 'crank'"),
        (lambda: ddb.zeitlin(8, 0.5, forcing=np.zeros((4, 4))), "forcing"),
        (lambda: ddb.zeitlin_vorticity("random", 100_000), "N = 100000"),
        (lambda: ddb.zeitlin_vorticity("random", 8, -1), "seed = -1"),
        (lambda: ddb.zeitlin_vorticity(None, 8), "kind = None"),
        (lambda: ddb.rigid_body([1, 2, 3], "0.5"), "alpha = '0.5'"),
        (lambda: ddb.heavy_top(mgl=[1]), "mgl = [1]"),
        (lambda: ddb.heavy_top(metric=[1, 1, 1]), "metric"),
        (lambda: ddb.integrate(ddb.heavy_top(), "sddb-paper-cay", ddb.HeavyTopSetup().mu0, 0.1,
                               1), "method = sddb-paper-cay"),
        (lambda: ddb.integrate(ddb.zeitlin(4, 0.5), "sddb-paper-exp",
                               ddb.zeitlin_vorticity("random", 4), 0.1, 1), "method"),
        (lambda: ddb.integrate(ddb.zeitlin(4, 0.5), "rk4", np.eye(4), 0.1, 1), "mu0"),
        (lambda: ddb.integrate(ddb.zeitlin(4, 0.5), "rk4", np.zeros((3, 3)), 0.1, 1), "mu0"),
        (lambda: ddb.rigid_body().energy(np.zeros((2, 2))), "states"),
    ]
    for make, parameter in cases:
        with pytest.raises(ValueError) as caught:
            make()
        assert str(caught.value).startswith(parameter), str(caught.value)


def test_an_unknown_method_lists_the_valid_ones():
    # For each family of groups, the message lists the methods that run on it, so that a typo
    # is mended from the message alone.
    a = ddb.scenario("A")
    cases = [(a.system(), a.mu0), (ddb.zeitlin(4, 0.5), ddb.zeitlin_vorticity("random", 4))]
    for system, mu0 in cases:
        with pytest.raises(ValueError) as caught:
            ddb.integrate(system, "ddb-kay", mu0, 0.1, 1)
        message = str(caught.value)
        assert message.startswith("method = ddb-kay"), message
        for name in system.methods():
            assert name in message, (name, message)


def test_numbers_in_messages_read_back_as_the_same_double():
    # The shortest form that reads back (0.1, not 0.10000000000000001).
    a = ddb.scenario("A")
    for h in (-0.1, -1e-300, -2.5e-8, -(1 / 3)):
        with pytest.raises(ValueError) as caught:
            ddb.integrate(a.system(), "ddb-cay", a.mu0, h, 1)
        written = str(caught.value).split(" is invalid")[0].removeprefix("h = ")
        assert float(written) == h, str(caught.value)
        assert written == repr(h), str(caught.value)


def test_a_matrix_for_manakovs_j_is_refused_saying_what_j_must_be():
    with pytest.raises(ValueError) as caught:
        ddb.manakov(np.ones((2, 2)), 0.5)
    message = str(caught.value)
    assert message.startswith("J = "), message
    assert "must be a 1-D array of N numbers" in message, message
    assert "not an array of 2 dimensions" in message, message
    assert "-1" not in message, message


def test_help_explains_every_argument():
    doc = ddb.integrate.__doc__
    for argument in ("system:", "method:", "mu0:", "h:", "steps:", "every:", "SolveFailure"):
        assert argument in doc


def test_integrate_releases_the_gil():
    # With no forced thread switches, the main thread can wake from its sleep during the
    # worker's integrate() only if integrate() released the GIL.
    a = ddb.scenario("A")
    started, done = threading.Event(), threading.Event()

    def work():
        started.set()
        ddb.integrate(a.system(), "ddb-cay", a.mu0, 0.1, 3_000_000, every=100_000)
        done.set()

    interval = sys.getswitchinterval()
    sys.setswitchinterval(1000.0)
    try:
        worker = threading.Thread(target=work)
        worker.start()
        while not started.is_set():
            time.sleep(0.001)
        time.sleep(0.01)
        woke_during_the_run = not done.is_set()
        worker.join()
    finally:
        sys.setswitchinterval(interval)
    assert woke_during_the_run


@pytest.mark.parametrize("method", ["ddb-cay", "sddb-exp", "rk4", "lobatto3c"])
def test_subnormal_components_are_flushed_and_the_run_stays_on_the_axis(method):
    # m = (0, c, 0) lies on a principal axis: the rigid body's equilibrium, with or without
    # dissipation (Omega = I^-1 m is parallel to m). Components below 2^-1022 start it.
    a = ddb.scenario("A")
    tiny = np.finfo(float).tiny  # 2^-1022, the smallest normal number
    _, m = ddb.integrate(a.system(), method, [tiny / 8, -0.5042, -tiny / 1e6], 0.1, 200)
    assert np.all(np.isfinite(m))
    _, axis = ddb.integrate(a.system(), method, [0.0, -0.5042, 0.0], 0.1, 200)
    np.testing.assert_allclose(axis, np.tile([0.0, -0.5042, 0.0], (201, 1)), rtol=1e-15, atol=0)
    np.testing.assert_array_equal(m[1:], axis[1:])


def test_a_decay_into_the_subnormal_range_ends_on_the_axis():
    # From a normal-range state, the off-axis components fall by about e^-0.009 a step until
    # they pass 2^-1022 (after some 7.6e4 steps): states then keep no subnormal numbers, and
    # the run ends at the limit point -|m0| e2 (Scenario B) with |m| kept.
    a = ddb.scenario("A")
    mu0 = np.array([1e-3, -0.5042, 1e-3])
    _, m = ddb.integrate(a.system(), "ddb-cay", mu0, 0.1, 200_000, every=1000)
    tiny = np.finfo(float).tiny
    assert np.all(np.isfinite(m))
    assert not np.any((m != 0) & (np.abs(m) < tiny))
    assert np.any((m[:, 0] != 0) & (np.abs(m[:, 0]) < 1e-300))  # it did pass close by
    np.testing.assert_array_equal(m[-1, [0, 2]], [0.0, 0.0])
    assert m[-1, 1] == pytest.approx(-np.linalg.norm(mu0), rel=1e-15)


# Under OpenBLAS's generic Prescott kernels on a CPU with AVX2 (what Debian 12's OpenBLAS picks
# on CPUs newer than itself), importing the module says so once, naming OPENBLAS_CORETYPE;
# under Haswell's kernels it says nothing (docs/guide/performance.md, "OpenBLAS's kernels").
def module_openblas_config():
    """The build configuration of the OpenBLAS the module itself links (not NumPy's), or ""."""
    listing = subprocess.run(["ldd", ddb.__file__], capture_output=True, text=True).stdout
    for line in listing.splitlines():
        if "libopenblas" in line and "=>" in line:
            library = ctypes.CDLL(line.split("=>")[1].split("(")[0].strip())
            library.openblas_get_config.restype = ctypes.c_char_p
            return library.openblas_get_config().decode()
    return ""


def test_import_says_once_when_openblas_runs_kernels_below_the_cpus():
    try:
        with open("/proc/cpuinfo") as info:
            flags = next(line for line in info if line.startswith("flags")).split()
    except (OSError, StopIteration):
        pytest.skip("no /proc/cpuinfo flags")
    if "avx2" not in flags or "fma" not in flags:
        pytest.skip("no AVX2: no kernels better than Prescott's to name")
    if "DYNAMIC_ARCH" not in module_openblas_config():
        pytest.skip("the module's BLAS is not an OpenBLAS that picks its kernels at load time")
    avx512 = all(f in flags for f in ("avx512f", "avx512bw", "avx512dq", "avx512vl"))
    for core in ("Prescott", "Haswell"):
        child = subprocess.run([sys.executable, "-c", "import ddb"], capture_output=True,
                               text=True, env={**os.environ, "OPENBLAS_CORETYPE": core})
        assert child.returncode == 0, child.stderr
        said = child.stderr.count("OPENBLAS_CORETYPE=")
        assert said == (1 if core == "Prescott" else 0), child.stderr
        if core == "Prescott":
            assert "RuntimeWarning" in child.stderr
            assert ("OPENBLAS_CORETYPE=SkylakeX" if avx512 else
                    "OPENBLAS_CORETYPE=Haswell") in child.stderr


def test_the_version_is_one_number_everywhere():
    # CMakeLists.txt's project version, the module's __version__, the package's
    # ddbConfigVersion.cmake of the build the module comes from, and a CHANGELOG section.
    root = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
    with open(os.path.join(root, "CMakeLists.txt")) as f:
        project = re.search(r"project\(ddb VERSION (\S+)", f.read()).group(1)
    assert ddb.__version__ == project
    config = os.path.join(os.path.dirname(ddb.__file__), "..", "ddbConfigVersion.cmake")
    if os.path.exists(config):  # a pip install has none
        with open(config) as f:
            assert re.search(r'set\(PACKAGE_VERSION "([^"]+)"\)', f.read()).group(1) == project
    with open(os.path.join(root, "CHANGELOG.md")) as f:
        headings = re.findall(r"^## (.*)$", f.read(), re.M)
    assert any(re.match(r"(Unreleased \()?%s\b" % re.escape(project), h) for h in headings), \
        headings
