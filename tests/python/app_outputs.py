"""What the app tests of this folder share: the app of this build from the environment ctest
sets (tests/CMakeLists.txt), an app's CSV file as columns, and a run killed mid-way."""
import csv
import os
import signal
import subprocess
import time

import numpy as np
import pytest


def app_path(variable):
    """The path in `variable`, or a skip saying that it is not set."""
    path = os.environ.get(variable)
    if not path:
        pytest.skip(f"{variable} (the app of this build) is not set")
    return path


def read_csv(path):
    """The columns of a CSV file with a header, as arrays by name."""
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    return {k: np.array([float(r[k]) for r in rows]) for k in rows[0]}


def kill_after_first_checkpoint(command, out):
    """Starts `command` (whose --out is `out`), sends it SIGKILL once out/checkpoint.ddb exists (at
    most 60 s) and waits for it; checks that it had not finished."""
    process = subprocess.Popen(command, stderr=subprocess.DEVNULL)
    deadline = time.monotonic() + 60
    while not (out / "checkpoint.ddb").exists() and time.monotonic() < deadline:
        time.sleep(0.001)
    process.send_signal(signal.SIGKILL)
    process.wait()
    assert not (out / "summary.json").exists(), "the run finished before the kill"
