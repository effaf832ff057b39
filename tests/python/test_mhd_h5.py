"""mhd-relax's fluid.hdf5 (docs/reference/command-lines-and-files.md, "mhd-relax") read back with
h5py, as quflow reads it: W's coefficients at the root, Theta's in the group theta, one frame per
row of history.csv. The energies and the cross helicity of each frame against their closed forms
in the coefficients (T_lm orthonormal for Re tr(A^H B)/N with Laplacian eigenvalue -l(l+1),
docs/reference/conventions.md §2): E_kin = sum omega^2/(2 l(l+1)), E_mag = sum l(l+1) theta^2/2,
cross helicity = sum omega theta/2, which the app computes from the matrices instead. A run
killed after a checkpoint and resumed has the uninterrupted run's frames, bit for bit.

ctest sets MHD_RELAX to the app of this build (tests/CMakeLists.txt).
"""
import json
import math
import subprocess

import numpy as np
import pytest
from app_outputs import app_path, kill_after_first_checkpoint, read_csv

h5py = pytest.importorskip("h5py", reason="h5py is not installed (Debian: python3-h5py)")

N = 8


def app():
    return app_path("MHD_RELAX")


@pytest.fixture(scope="module")
def run(tmp_path_factory):
    out = tmp_path_factory.mktemp("mhd_h5")
    subprocess.run([app(), "--n", str(N), "--steps", "25", "--every", "4", "--alpha", "0.05",
                    "--theta-scale", "0.3", "--quiet", "--out", str(out)], check=True,
                   capture_output=True)
    return out


def degrees():
    """l of each index l^2 + l + m."""
    return np.array([l for l in range(N) for _ in range(2 * l + 1)])


def test_layout_and_attributes(run):
    history = read_csv(run / "history.csv")
    with open(run / "summary.json") as f:
        summary = json.load(f)
    with h5py.File(run / "fluid.hdf5", "r") as f:
        frames = len(history["t"])
        assert frames == 8  # k = 0, 4, ..., 24 and the last, 25
        for group in (f, f["theta"]):
            assert group["state"].shape == (frames, N * N)
            assert group["state"].attrs["qtype"] == "shr"
            assert group.attrs["N"] == N
            np.testing.assert_array_equal(group["time"][:], history["t"])
            hbar = 2 / math.sqrt(N * N - 1)
            np.testing.assert_allclose(group["qtime"][:], history["t"] / hbar, rtol=1e-15)
        np.testing.assert_array_equal(f["step"][:], [0, 4, 8, 12, 16, 20, 24, 25])
        for column in ("kinetic_energy", "magnetic_energy", "cross_helicity", "residual",
                       "equilibrium_residual", "invariant_drift"):
            np.testing.assert_array_equal(f[column][:], history[column])
        assert f.attrs["method"] == summary["method"] == "ddb-cay"
        assert f.attrs["alpha"] == 0.05
        assert f.attrs["theta_init"] == "low-modes"


def test_energies_are_their_closed_forms_in_the_coefficients(run):
    history = read_csv(run / "history.csv")
    l = degrees()
    with h5py.File(run / "fluid.hdf5", "r") as f:
        omega, theta = f["state"][:], f["theta/state"][:]
    # l = 0 carries nothing: W and Theta are traceless.
    np.testing.assert_allclose(omega[:, 0], 0, atol=1e-14)
    np.testing.assert_allclose(theta[:, 0], 0, atol=1e-14)
    w, t, ll = omega[:, 1:], theta[:, 1:], (l * (l + 1))[1:]
    np.testing.assert_allclose((w**2 / ll).sum(axis=1) / 2, history["kinetic_energy"], rtol=1e-12)
    np.testing.assert_allclose((t**2 * ll).sum(axis=1) / 2, history["magnetic_energy"], rtol=1e-12)
    np.testing.assert_allclose((w * t).sum(axis=1) / 2, history["cross_helicity"], rtol=1e-11)
    # The cross helicity is a Casimir, the total energy falls (alpha > 0).
    np.testing.assert_allclose(history["cross_helicity"], history["cross_helicity"][0], rtol=1e-13)
    assert np.all(np.diff(history["energy"]) < 0)


def test_a_killed_run_resumes_to_the_same_frames(tmp_path):
    """SIGKILL after the first checkpoint, then --resume: fluid.hdf5's frames are the
    uninterrupted run's, bit for bit (the file is flushed before each checkpoint and cut back to
    its frames on resume)."""
    args = ["--n", "12", "--every", "7", "--checkpoint-every", "50", "--steps", "3000",
            "--quiet"]
    whole, killed = tmp_path / "whole", tmp_path / "killed"
    subprocess.run([app(), *args, "--out", str(whole)], check=True, capture_output=True)
    kill_after_first_checkpoint([app(), *args, "--out", str(killed)], killed)
    subprocess.run([app(), "--resume", str(killed), "--quiet"], check=True, capture_output=True)
    rows = len(read_csv(killed / "history.csv")["t"])
    with h5py.File(whole / "fluid.hdf5", "r") as a, h5py.File(killed / "fluid.hdf5", "r") as b:
        assert b["state"].shape[0] == rows
        for name in ("state", "theta/state", "time", "qtime", "theta/time", "theta/qtime", "step",
                     "kinetic_energy", "magnetic_energy", "cross_helicity", "residual",
                     "equilibrium_residual", "invariant_drift"):
            assert np.array_equal(a[name][()], b[name][()]), name
