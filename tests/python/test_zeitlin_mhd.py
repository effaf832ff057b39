"""ddb.zeitlin_mhd: magnetohydrodynamics on the sphere from Python (states (2, N, N), [W, Theta]).

Checked against what the module did not compute this way: Zeitlin's fluid (ddb.zeitlin) at
Theta = 0, bit for bit; the invariants tr Theta^k and tr(W Theta^k) computed here with NumPy; the
energies' closed forms from the fluid's own stream matrix.
"""
import numpy as np
import pytest

import ddb


def skew_hermitian_traceless(rng, n):
    a = rng.standard_normal((n, n)) + 1j * rng.standard_normal((n, n))
    x = (a - a.conj().T) / 2
    return x - np.trace(x) / n * np.eye(n)


def test_states_are_w_then_theta_and_methods_all_of_the_matrix_groups_but_the_reference():
    mhd = ddb.zeitlin_mhd(8, 0.1)
    assert mhd.state_shape == (2, 8, 8)
    assert mhd.n == 8
    assert mhd.methods() == ["ddb-cay", "ddb-exp", "ddb-exp-exact", "ddb-cay-implicit",
                             "ddb-exp-implicit", "sddb-cay", "sddb-exp", "ddb4-cay", "ddb4-exp",
                             "ddb6-exp", "rk4", "lobatto3c"]


def test_without_magnetic_field_it_is_the_fluid_to_the_bit():
    n = 10
    W0 = ddb.zeitlin_vorticity("random", n, 3)
    fluid, mhd = ddb.zeitlin(n, 0.5), ddb.zeitlin_mhd(n, 0.5)
    _, fluid_explicit = ddb.integrate(fluid, "ddb-cay", W0, 0.02, 15)
    for method in mhd.methods():
        _, fluid_states = ddb.integrate(fluid, method, W0, 0.02, 15)
        _, mhd_states = ddb.integrate(mhd, method, np.stack([W0, np.zeros_like(W0)]), 0.02, 15)
        assert mhd_states.shape == (16, 2, n, n)
        if method.endswith("-implicit"):
            # Their factor's CG is preconditioned otherwise on the dual numbers (by the shift, on
            # the fluid by mu's eigenbasis): W is the fluid's to its tolerance, closer than the
            # fluid's DDB step with the explicit factor, which differs by O(h^2) a step.
            distance = np.linalg.norm(mhd_states[1:, 0] - fluid_states[1:], axis=(1, 2))
            scale = np.linalg.norm(fluid_explicit[1:] - fluid_states[1:], axis=(1, 2))
            assert np.all(distance < scale), method
        else:
            assert np.array_equal(mhd_states[:, 0], fluid_states), method
        assert not np.any(mhd_states[:, 1]), method
    # The kinetic energy is the fluid's energy.
    assert mhd.kinetic_energy(np.stack([W0, 0 * W0])) == pytest.approx(fluid.fluid_energy(W0),
                                                                       rel=1e-13)


@pytest.mark.parametrize("method", ["ddb-cay", "sddb-exp", "ddb-cay-implicit"])
def test_relaxation_keeps_both_invariant_families_and_lowers_the_energy(method):
    n, alpha = 12, 0.5
    rng = np.random.default_rng(5)
    W0 = ddb.zeitlin_vorticity("l1", n, 2)
    Theta0 = 0.02 * skew_hermitian_traceless(rng, n) / np.sqrt(n)
    mhd = ddb.zeitlin_mhd(n, alpha)
    _, states = ddb.integrate(mhd, method, np.stack([W0, Theta0]), 0.01, 300, every=10)
    energy = mhd.energy(states)
    assert np.all(np.diff(energy) <= 1e-14 * energy[0])
    assert energy[-1] < energy[0]
    total = mhd.kinetic_energy(states) + mhd.magnetic_energy(states)
    assert np.allclose(total, energy * 2 / np.sqrt(n * n - 1) / n, rtol=1e-13)
    # tr Theta^k and tr(W Theta^k), here with NumPy, for k = 1..4.
    for k in range(1, 5):
        first = [np.trace(np.linalg.matrix_power(s[1], k)) for s in states]
        mixed = [np.trace(s[0] @ np.linalg.matrix_power(s[1], k)) for s in states]
        for values in (first, mixed):
            scale = max(abs(values[0]), np.linalg.norm(Theta0, 2) ** k * n)
            assert np.max(np.abs(np.array(values) - values[0])) < 1e-12 * scale, k
    assert mhd.cross_helicity(states) == pytest.approx(
        np.full(len(states), mhd.cross_helicity(states[0])), rel=1e-12)
    assert mhd.residual(states[-1]) < mhd.residual(states[0])


def test_diagnostics_and_fields_on_the_grid():
    n = 9
    fluid, mhd = ddb.zeitlin(n, 0.0), ddb.zeitlin_mhd(n, 0.0)
    W = ddb.zeitlin_vorticity("random", n, 1)
    Theta = 0.1 * ddb.zeitlin_vorticity("random", n, 2)
    mu = np.stack([W, Theta])
    P = fluid.stream_matrix(W)
    assert mhd.kinetic_energy(mu) == pytest.approx(np.trace(W @ P).real / (2 * n), rel=1e-12)
    assert mhd.magnetic_energy(mu) > 0
    assert mhd.cross_helicity(mu) == pytest.approx(-np.trace(W @ Theta).real / (2 * n),
                                                   rel=1e-12)
    omega = mhd.omega_lm(mu)
    assert omega.shape == (2, n * n)
    assert np.allclose(omega[0], fluid.omega_lm(W), rtol=0, atol=1e-14)
    grid_w, grid_theta = mhd.fields_on_grid(mu)
    assert grid_w.shape == (n, 2 * n - 1) and grid_theta.shape == (n, 2 * n - 1)
    assert np.allclose(grid_w, fluid.vorticity_on_grid(W), rtol=0, atol=1e-12)


def test_bad_inputs_name_the_parameter():
    n = 6
    mhd = ddb.zeitlin_mhd(n, 0.1)
    W = ddb.zeitlin_vorticity("random", n, 1)
    with pytest.raises(ValueError, match="mu0.*shape \\(2, 6, 6\\)"):
        ddb.integrate(mhd, "ddb-cay", W, 0.1, 1)
    not_skew = W.copy()
    not_skew[0, 1] += 1
    with pytest.raises(ValueError, match=r"mu0\[1\] \(Theta\)"):
        ddb.integrate(mhd, "ddb-cay", np.stack([W, not_skew]), 0.1, 1)
    nan = W.copy()
    nan[2, 3] = np.nan
    with pytest.raises(ValueError, match=r"mu0\[0\] \(W\)"):
        ddb.integrate(mhd, "ddb-cay", np.stack([nan, W]), 0.1, 1)
    with pytest.raises(ValueError, match=r"method.*reference"):
        ddb.integrate(mhd, "reference", np.stack([W, W]), 0.1, 1)
    with pytest.raises(ValueError, match="N"):
        ddb.zeitlin_mhd(1, 0.1)
    with pytest.raises(ValueError, match="alpha"):
        ddb.zeitlin_mhd(8, float("nan"))
