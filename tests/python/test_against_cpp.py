"""Every system and method of the module gives the C++ run's numbers bit for bit.

The reference is the ddb-compare app of the same build (its summary.json final states, written
in the shortest form that reads back to the same double; tests/apps/test_ddb_compare*.cc check them
equal to makeMethod runs), not code of the module.
"""
import numpy as np
import pytest

import ddb


def final_state(entry):
    final = entry["final"]
    if isinstance(final, dict):
        return np.array(final["re"]) + 1j * np.array(final["im"])
    return np.array(final)


def check_methods(summary, system, mu0, every_method=True):
    """Each method ddb-compare ran (every one that applies, if `every_method`) gives its final
    state bit for bit."""
    if every_method:
        assert sorted(summary["methods"]) == sorted(system.methods())
    for name, entry in summary["methods"].items():
        assert entry["status"] == "ok", name
        t, states = ddb.integrate(system, name, mu0, summary["h"], summary["steps"])
        assert t[-1] == entry["t_final"], name
        expected = final_state(entry)
        if states.dtype == np.float64 and expected.dtype == np.complex128:
            assert not expected.imag.any(), name  # SO(N): im all zeros
            expected = expected.real
        np.testing.assert_array_equal(states[-1], expected, err_msg=name)


def test_rigid_body_scenario_a(ddb_compare, tmp_path):
    summary = ddb_compare(tmp_path, "--system", "rigid-body", "--scenario", "A", "--h", "0.1",
                          "--t-end", "3")
    a = ddb.scenario("A")
    check_methods(summary, a.system(), a.mu0)


def test_rigid_body_custom_parameters(ddb_compare, tmp_path):
    summary = ddb_compare(tmp_path, "--system", "rigid-body", "--inertia", "2,1.5,0.7",
                          "--alpha", "0.3", "--omega0", "0.4,-0.2,0.9", "--h", "0.07",
                          "--t-end", "2.1", "--method", "ddb-cay,sddb-exp,ddb6-exp,lobatto3c")
    system = ddb.rigid_body([2, 1.5, 0.7], 0.3)
    check_methods(summary, system, np.array([2, 1.5, 0.7]) * [0.4, -0.2, 0.9], False)


def test_heavy_top(ddb_compare, tmp_path):
    summary = ddb_compare(tmp_path, "--system", "heavy-top", "--h", "0.1", "--t-end", "2")
    setup = ddb.HeavyTopSetup()
    check_methods(summary, ddb.heavy_top(), setup.mu0)
    assert setup.system().name == "heavy-top"


def test_kirchhoff(ddb_compare, tmp_path):
    summary = ddb_compare(tmp_path, "--system", "kirchhoff", "--h", "0.1", "--t-end", "2")
    check_methods(summary, ddb.kirchhoff(), ddb.KirchhoffSetup().mu0)


def test_planar_kirchhoff(ddb_compare, tmp_path):
    summary = ddb_compare(tmp_path, "--system", "planar-kirchhoff", "--h", "0.1", "--t-end", "2")
    setup = ddb.PlanarKirchhoffSetup()
    check_methods(summary, ddb.planar_kirchhoff(), setup.mu0)
    assert setup.system().group == "SE2"


def test_planar_kirchhoff_custom_parameters(ddb_compare, tmp_path):
    summary = ddb_compare(tmp_path, "--system", "planar-kirchhoff", "--inertia", "0.7",
                          "--mass", "2,1.5", "--alpha", "0.2", "--metric", "1,0.5,2",
                          "--mu0", "0.1,-0.4,0.8", "--h", "0.05", "--t-end", "1")
    system = ddb.planar_kirchhoff(0.7, [2, 1.5], 0.2, [1, 0.5, 2])
    check_methods(summary, system, np.array([0.1, -0.4, 0.8]))


def test_manakov_from_a_file(ddb_compare, tmp_path):
    rng = np.random.default_rng(7)
    a = rng.standard_normal((4, 4))
    m0 = a - a.T
    path = tmp_path / "m0.csv"
    path.write_text("\n".join(",".join(repr(float(x)) for x in row) for row in m0) + "\n")
    J = [1.0, 1.25, 1.7, 2.0]
    summary = ddb_compare(tmp_path / "out", "--system", "manakov", "--mu0-file", str(path),
                          "--j", ",".join(map(repr, J)), "--alpha", "0.4", "--h", "0.05",
                          "--t-end", "0.5")
    check_methods(summary, ddb.manakov(J, 0.4), m0)


def test_zeitlin_seeded_random_vorticity(ddb_compare, tmp_path):
    summary = ddb_compare(tmp_path, "--system", "zeitlin", "--n", "6", "--init", "random",
                          "--seed", "3", "--alpha", "0.5", "--h", "0.05", "--t-end", "0.3")
    check_methods(summary, ddb.zeitlin(6, 0.5), ddb.zeitlin_vorticity("random", 6, 3))


@pytest.mark.parametrize("kind", ["l1", "zonal"])
def test_zeitlin_other_initial_vorticities(ddb_compare, tmp_path, kind):
    summary = ddb_compare(tmp_path, "--system", "zeitlin", "--n", "5", "--init", kind, "--seed",
                          "11", "--h", "0.1", "--t-end", "0.2", "--method", "ddb-cay,rk4")
    check_methods(summary, ddb.zeitlin(5, 0.5), ddb.zeitlin_vorticity(kind, 5, 11), False)
