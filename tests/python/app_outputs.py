"""What the app tests of this folder share: the app of this build from the environment ctest
sets (tests/CMakeLists.txt), and an app's CSV file as columns."""
import csv
import os

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
