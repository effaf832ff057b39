"""fluid-relax --h5 (docs/reference/command-lines-and-files.md, "fluid.hdf5") read back with
h5py, as quflow reads it, and checked against the CSV files the app writes through its other
code path:
W_final.csv (mat), omega_initial.csv and omega_final.csv (state, quflow's index
l^2 + l + m), history.csv (time and the diagnostics, one frame per row). The field diagnostics
(spectra, gamma, the scale decomposition, the grid "fun") against what numpy and scipy compute
from the frames' matrices and coefficients, and against the sums they must have.

ctest sets FLUID_RELAX to the app of this build and DDB_ANIMATE_SCRIPT to
scripts/animate_fluid.py (tests/CMakeLists.txt).
"""
import datetime
import json
import math
import os
import subprocess
import sys

import numpy as np
import pytest
from app_outputs import app_path, kill_after_first_checkpoint, read_csv

h5py = pytest.importorskip("h5py", reason="h5py is not installed (Debian: python3-h5py)")

N = 8


def app():
    return app_path("FLUID_RELAX")


def omega_in_quflow_order(path):
    """omega_*.csv's rows (l, m, omega) placed at index l^2 + l + m."""
    columns = read_csv(path)
    omega = np.full(N * N, np.nan)
    for l, m, w in zip(columns["l"], columns["m"], columns["omega"]):
        omega[int(l) ** 2 + int(l) + int(m)] = w
    return omega


@pytest.fixture(scope="module")
def run(tmp_path_factory):
    out = tmp_path_factory.mktemp("fluid_h5")
    subprocess.run([app(), "--n", str(N), "--steps", "5", "--every", "2", "--h5", "--quiet",
                    "--out", str(out)], check=True, capture_output=True)
    return out


def test_layout_and_attributes(run):
    with open(run / "summary.json") as f:
        summary = json.load(f)
    with h5py.File(run / "fluid.hdf5", "r") as f:
        frames = f["state"].shape[0]
        assert frames == 4  # steps 0, 2, 4 and the last, 5
        assert f["state"].shape == (frames, N * N) and f["state"].dtype == np.float64
        assert f["state"].attrs["qtype"] == "shr"  # a str, as quflow.load compares it
        assert f["mat"].shape == (frames, N, N) and f["mat"].dtype == np.complex128
        for name in ("time", "qtime", "energy_euler", "enstrophy", "commutator_norm",
                     "spectrum_drift"):
            assert f[name].shape == (frames,) and f[name].dtype == np.float64, name
        assert f["step"].dtype == np.int64
        assert list(f["step"][:]) == [0, 2, 4, 5]
        for name in ("state", "mat", "time", "step"):
            assert f[name].maxshape[0] is None, name  # extendable
        a = f.attrs
        assert a["N"] == N and a["alpha"] == summary["alpha"] and a["h"] == summary["h"]
        assert a["method"] == summary["method"] and a["init"] == summary["init"]
        assert a["seed"] == summary["seed"] and "init_file" not in a
        assert a["version"] == summary["version"]
        created = datetime.datetime.strptime(a["created"], "%Y-%m-%dT%H:%M:%SZ")
        assert abs(datetime.datetime.utcnow() - created) < datetime.timedelta(minutes=10)


def test_frames_equal_the_csv_files(run):
    history = read_csv(run / "history.csv")
    final = np.loadtxt(run / "W_final.csv", delimiter=",")
    with h5py.File(run / "fluid.hdf5", "r") as f:
        assert f["state"].shape[0] == history["t"].size
        # %.17g round-trips a double: equal, not close.
        np.testing.assert_array_equal(f["mat"][-1], final[:, :N] + 1j * final[:, N:])
        np.testing.assert_array_equal(f["state"][0], omega_in_quflow_order(run / "omega_initial.csv"))
        np.testing.assert_array_equal(f["state"][-1], omega_in_quflow_order(run / "omega_final.csv"))
        np.testing.assert_array_equal(f["time"][:], history["t"])
        for name, column in (("energy_euler", "energy"), ("enstrophy", "enstrophy"),
                             ("commutator_norm", "commutator_norm"),
                             ("spectrum_drift", "spectrum_drift")):
            np.testing.assert_array_equal(f[name][:], history[column], err_msg=name)
        # quflow's qtime: time in units of hbar = 2/sqrt(N^2 - 1) (quflow.utils.qtime2seconds).
        hbar = 2.0 / math.sqrt(N * N - 1)
        np.testing.assert_allclose(f["qtime"][:] * hbar, history["t"], rtol=1e-15, atol=0)


def grid_from_coefficients(omega, n):
    """sqrt(4 pi) sum omega_lm Y_lm on quflow's grid (N x (2N - 1), MW sampling), Y_lm the real
    harmonics of docs/reference/conventions.md from scipy's complex ones (Condon-Shortley)."""
    from scipy.special import sph_harm
    theta = np.pi * (2 * np.arange(n) + 1) / (2 * n - 1)
    phi = 2 * np.pi * np.arange(2 * n - 1) / (2 * n - 1)
    P, T = np.meshgrid(phi, theta)
    f = np.zeros_like(T)
    for l in range(n):
        for m in range(-l, l + 1):
            y = sph_harm(abs(m), l, P, T)
            if m > 0:
                y = math.sqrt(2) * (-1) ** m * y.real
            elif m < 0:
                y = math.sqrt(2) * (-1) ** m * y.imag
            else:
                y = y.real
            f += omega[l * l + l + m] * y
    return math.sqrt(4 * math.pi) * f


def test_field_diagnostics(run):
    pytest.importorskip("scipy", reason="scipy is not installed (Debian: python3-scipy)")
    history = read_csv(run / "history.csv")
    with h5py.File(run / "fluid.hdf5", "r") as f:
        frames = f["state"].shape[0]
        assert f["fun"].shape == (frames, N, 2 * N - 1)
        assert f["fun"].attrs["qtype"] == "fun"
        assert f["energy_spectrum"].shape == (frames, N)
        np.testing.assert_array_equal(f["gamma"][:], history["gamma"])
        for i in range(frames):
            omega, W = f["state"][i], f["mat"][i]
            # The spectra sum to the energy and the enstrophy (history.csv's, from traces).
            assert f["energy_spectrum"][i].sum() == pytest.approx(history["energy"][i], rel=1e-12)
            assert f["enstrophy_spectrum"][i].sum() == pytest.approx(history["enstrophy"][i],
                                                                     rel=1e-12)
            assert f["enstrophy_spectrum"][i][2] == pytest.approx(0.5 * np.sum(omega[4:9] ** 2),
                                                                  rel=1e-12)
            assert f["gamma"][i] == pytest.approx(np.linalg.norm(omega[1:4]) /
                                                  np.linalg.norm(omega), rel=1e-12)
            # The scale decomposition is orthogonal (W_s is W's diagonal in psi's eigenbasis):
            # its two enstrophies, computed apart, sum to W's (tests/unit/test_zeitlin_spectra.cc
            # checks W_s itself).
            steady, remainder = f["enstrophy_steady"][i], f["enstrophy_remainder"][i]
            assert steady + remainder == pytest.approx(history["enstrophy"][i], rel=1e-12)
            assert 0 < steady < history["enstrophy"][i]
            np.testing.assert_allclose(f["fun"][i], grid_from_coefficients(omega, N),
                                       rtol=0, atol=1e-12 * np.abs(f["fun"][i]).max())


def test_bad_input_creates_nothing(tmp_path):
    out = tmp_path / "out"
    result = subprocess.run([app(), "--n", "1", "--steps", "5", "--h5", "--out", str(out)],
                            capture_output=True, text=True)
    assert result.returncode == 2
    assert "--n" in result.stderr
    assert not out.exists()


def test_animation_without_ffmpeg_writes_nothing(run, tmp_path):
    script = os.environ.get("DDB_ANIMATE_SCRIPT")
    if not script:
        pytest.skip("DDB_ANIMATE_SCRIPT (scripts/animate_fluid.py) is not set")
    video = tmp_path / "fluid.mp4"
    result = subprocess.run([sys.executable, script, str(run / "fluid.hdf5"), str(video)],
                            capture_output=True, text=True,
                            env={**os.environ, "PATH": str(tmp_path)})
    assert result.returncode == 1
    assert "ffmpeg" in result.stderr
    assert list(tmp_path.iterdir()) == []


def test_a_killed_and_resumed_run_has_one_frame_per_row_and_the_uninterrupted_frames(
        tmp_path):
    """SIGKILL right after the first checkpoint, then --resume: fluid.hdf5 is cut back to the
    checkpoint's frames and continued, so that it holds exactly the uninterrupted run's
    frames (docs/reference/command-lines-and-files.md, "Checkpoints")."""
    args = ["--n", "12", "--seed", "4", "--every", "7", "--checkpoint-every", "50",
            "--steps", "4000", "--h5", "--quiet"]
    whole, killed = tmp_path / "whole", tmp_path / "killed"
    subprocess.run([app(), *args, "--out", str(whole)], check=True, capture_output=True)
    kill_after_first_checkpoint([app(), *args, "--out", str(killed)], killed)
    subprocess.run([app(), "--resume", str(killed), "--quiet"], check=True, capture_output=True)
    rows = len(read_csv(killed / "history.csv")["t"])
    with h5py.File(whole / "fluid.hdf5", "r") as a, h5py.File(killed / "fluid.hdf5", "r") as b:
        assert b["state"].shape[0] == rows
        for name in ("state", "mat", "time", "qtime", "step", "energy_euler", "enstrophy",
                     "commutator_norm", "spectrum_drift"):
            assert np.array_equal(a[name][()], b[name][()]), name
