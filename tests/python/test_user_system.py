"""Systems whose Hamiltonian is written in Python equal the library's own systems."""
import numpy as np
import pytest

import ddb

INERTIA = np.array([1.0, 1.3, 0.5])


def python_rigid_body(alpha, hessian=True):
    return ddb.user_system(
        "SO3",
        hamiltonian=lambda m: 0.5 * float(np.sum(m * m / INERTIA)),
        gradient=lambda m: m / INERTIA,
        hessian_times=(lambda m, v: v / INERTIA) if hessian else None,
        alpha=alpha, name="python-rigid-body")


@pytest.mark.parametrize("method", [m for m in ddb.rigid_body().methods()
                                    if not m.startswith("sddb-paper")])
def test_python_rigid_body_equals_the_library_one(method):
    a = ddb.scenario("A")
    user = python_rigid_body(a.alpha)
    assert method in user.methods()
    _, expected = ddb.integrate(a.system(), method, a.mu0, 0.1, 50)
    _, got = ddb.integrate(user, method, a.mu0, 0.1, 50)
    np.testing.assert_allclose(got, expected, rtol=0, atol=1e-13)
    np.testing.assert_allclose(user.energy(got), a.system().energy(expected), atol=1e-13)


def test_without_a_hessian_the_central_difference_serves():
    a = ddb.scenario("A")
    _, expected = ddb.integrate(a.system(), "lobatto3c", a.mu0, 0.1, 50)
    _, got = ddb.integrate(python_rigid_body(a.alpha, hessian=False), "lobatto3c", a.mu0, 0.1, 50)
    np.testing.assert_allclose(got, expected, rtol=0, atol=1e-13)


def test_the_paper_variants_need_a_lagrangian():
    user = python_rigid_body(0.5)
    assert "sddb-paper-cay" not in user.methods()
    with pytest.raises(ValueError, match="method = sddb-paper-cay"):
        ddb.integrate(user, "sddb-paper-cay", [0, 0.065, 0.5], 0.1, 1)


def test_python_manakov_body_on_so_n():
    J = np.array([1.0, 1.3, 1.6, 2.2])
    inverse = 1.0 / (J[:, None] + J[None, :])
    user = ddb.user_system("SO(N)", lambda M: 0.5 * float(np.sum(M * M * inverse)),
                           lambda M: M * inverse, lambda M, V: V * inverse, alpha=0.5, N=4)
    rng = np.random.default_rng(3)
    a = rng.standard_normal((4, 4))
    m0 = a - a.T
    for method in ("ddb-cay", "sddb-exp", "rk4", "lobatto3c"):
        _, expected = ddb.integrate(ddb.manakov(J, 0.5), method, m0, 0.05, 20)
        _, got = ddb.integrate(user, method, m0, 0.05, 20)
        np.testing.assert_allclose(got, expected, rtol=0, atol=1e-13, err_msg=method)


def test_python_fluid_on_su_n():
    fluid = ddb.zeitlin(5, 0.5)
    hbar = fluid.hbar
    user = ddb.user_system(
        "SU(N)", lambda W: float(np.real(np.trace(W @ fluid.stream_matrix(W)))) / (2 * hbar),
        lambda W: -fluid.stream_matrix(W) / hbar, lambda W, V: -fluid.stream_matrix(V) / hbar,
        alpha=0.5, N=5)
    W0 = ddb.zeitlin_vorticity("random", 5, 9)
    assert user.energy(W0) == pytest.approx(fluid.energy(W0), rel=1e-14)
    for method in ("ddb-cay", "ddb4-exp", "rk4"):
        _, expected = ddb.integrate(fluid, method, W0, 0.05, 20)
        _, got = ddb.integrate(user, method, W0, 0.05, 20)
        np.testing.assert_allclose(got, expected, rtol=0, atol=1e-13, err_msg=method)


def test_errors_of_a_python_hamiltonian_reach_the_caller():
    def broken(m):
        raise ZeroDivisionError("inside the user's gradient")

    user = ddb.user_system("SO3", lambda m: 0.0, broken, alpha=0.5)
    with pytest.raises(ZeroDivisionError, match="inside the user's gradient"):
        ddb.integrate(user, "ddb-cay", [0, 0.065, 0.5], 0.1, 3)
    wrong = ddb.user_system("SO3", lambda m: 0.0, lambda m: np.zeros(4), alpha=0.5)
    with pytest.raises(ValueError, match="^gradient = an array of shape"):
        ddb.integrate(wrong, "rk4", [0, 0.065, 0.5], 0.1, 3)
    with pytest.raises(ValueError, match="^group = SO5"):
        ddb.user_system("SO5", lambda m: 0.0, lambda m: m)
    with pytest.raises(ValueError, match="^N = 1"):
        ddb.user_system("SU(N)", lambda m: 0.0, lambda m: m, N=1)
    with pytest.raises(ValueError, match="^metric"):
        ddb.user_system("SO(N)", lambda m: 0.0, lambda m: m, N=3, metric=[1, 1, 1])


@pytest.mark.parametrize("kwargs, parameter", [
    (dict(hamiltonian=5), "hamiltonian = 5"),
    (dict(gradient="m / I"), "gradient = 'm / I'"),
    (dict(hessian_times=1.0), "hessian_times = 1.0"),
    (dict(group=3), "group = 3"),
    (dict(alpha=None), "alpha = None"),
    (dict(N="4"), "N = '4'"),
    (dict(group="SO(N)", N=100_000), "N = 100000"),
    (dict(name=7), "name = 7"),
])
def test_bad_user_system_arguments_name_the_parameter(kwargs, parameter):
    args = dict(group="SO3", hamiltonian=lambda m: 0.0, gradient=lambda m: m)
    args.update(kwargs)
    with pytest.raises(ValueError) as caught:
        ddb.user_system(**args)
    assert str(caught.value).startswith(parameter), str(caught.value)


def test_a_hamiltonian_that_returns_no_number_is_named():
    user = ddb.user_system("SO3", lambda m: "0.5", lambda m: m / INERTIA, alpha=0.5)
    with pytest.raises(ValueError, match="^hamiltonian = a function returning '0.5'"):
        user.energy([0, 0.065, 0.5])


def test_a_non_finite_gradient_fails_the_step_and_keeps_the_states_before_it():
    # rk4 calls the gradient 4 times a step (its 4 stages): call 4 * 7 + 1 is step 7's first.
    a = ddb.scenario("A")
    calls = 0

    def gradient(m):
        nonlocal calls
        calls += 1
        return m / INERTIA if calls <= 4 * 7 else np.array([np.nan, 0.0, 0.0])

    user = ddb.user_system("SO3", lambda m: 0.0, gradient, alpha=a.alpha)
    with pytest.raises(ddb.SolveFailure) as caught:
        ddb.integrate(user, "rk4", a.mu0, 0.1, 20)
    e = caught.value
    assert (e.kind, e.step, e.h) == ("NonFiniteState", 7, 0.1)
    assert "gradient" in str(e) and "step 7 " in str(e)
    _, expected = ddb.integrate(a.system(), "rk4", a.mu0, 0.1, 7)
    np.testing.assert_allclose(e.states, expected, rtol=0, atol=1e-13)
    np.testing.assert_allclose(e.times, 0.1 * np.arange(8), rtol=1e-15)


def test_a_non_finite_hessian_or_energy_is_a_solve_failure():
    a = ddb.scenario("A")
    user = ddb.user_system("SO3", lambda m: float("inf"), lambda m: m / INERTIA,
                           lambda m, v: np.full(3, np.nan), alpha=a.alpha)
    # lobatto3c's stage equations are solved by Newton on the Hessian product from step 0.
    with pytest.raises(ddb.SolveFailure) as caught:
        ddb.integrate(user, "lobatto3c", a.mu0, 0.1, 5)
    assert caught.value.kind == "NonFiniteState" and "hessian_times" in str(caught.value)
    np.testing.assert_array_equal(caught.value.states, [a.mu0])
    with pytest.raises(ddb.SolveFailure, match="hamiltonian = inf"):
        user.energy(a.mu0)


def test_a_diagonal_metric_on_se3_equals_the_heavy_top():
    setup = ddb.HeavyTopSetup()
    k = np.array([1.0, 2.0, 0.5, 1.0, 1.0, 3.0])
    inv = 1.0 / np.asarray(setup.inertia)
    chi = setup.mgl * np.asarray(setup.chi)
    user = ddb.user_system(
        "SE3", lambda mu: 0.5 * float(np.sum(mu[:3]**2 * inv)) + float(chi @ mu[3:]),
        lambda mu: np.concatenate([mu[:3] * inv, chi]), alpha=0.5, metric=k)
    _, expected = ddb.integrate(ddb.heavy_top(metric=k), "sddb-cay", setup.mu0, 0.1, 30)
    _, got = ddb.integrate(user, "sddb-cay", setup.mu0, 0.1, 30)
    np.testing.assert_allclose(got, expected, rtol=0, atol=1e-13)


def test_python_planar_body_equals_the_library_one():
    # Kirchhoff's planar body, H = pi^2/(2 I) + P1^2/(2 m1) + P2^2/(2 m2), on SE2 with a diagonal
    # metric: every method but the Lagrangian-only ones follows the library's system.
    setup = ddb.PlanarKirchhoffSetup()
    weights = 1.0 / np.array([setup.inertia, setup.mass[0], setup.mass[1]])
    user = ddb.user_system(
        "SE2",
        hamiltonian=lambda mu: 0.5 * float(np.sum(weights * mu * mu)),
        gradient=lambda mu: weights * mu,
        hessian_times=lambda mu, v: weights * v,
        alpha=setup.alpha, metric=setup.metric, name="python-planar-body")
    assert user.group == "SE2" and user.state_shape == (3,)
    for method in user.methods():
        _, expected = ddb.integrate(setup.system(), method, setup.mu0, 0.1, 50)
        _, got = ddb.integrate(user, method, setup.mu0, 0.1, 50)
        np.testing.assert_allclose(got, expected, rtol=0, atol=1e-13, err_msg=method)
