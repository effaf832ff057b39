"""Shared fixtures of the Python tests: the module and the ddb-compare app of the same build.

ctest sets PYTHONPATH to the module's folder and DDB_COMPARE to the app (tests/CMakeLists.txt).
"""
import importlib.util
import json
import os
import pathlib
import subprocess

import pytest

SCRIPTS = pathlib.Path(__file__).resolve().parents[2] / "scripts"


@pytest.fixture(scope="session")
def load_script():
    """Imports scripts/NAME.py as a module (its main() not run)."""

    def load(name):
        spec = importlib.util.spec_from_file_location(name, SCRIPTS / (name + ".py"))
        module = importlib.util.module_from_spec(spec)
        spec.loader.exec_module(module)
        return module

    return load


@pytest.fixture(scope="session")
def ddb_compare():
    """Runs ddb-compare with `args` in a fresh folder and returns its summary.json."""
    path = os.environ.get("DDB_COMPARE")
    if not path:
        pytest.skip("DDB_COMPARE (the ddb-compare of this build) is not set")

    def run(out, *args):
        subprocess.run([path, "--out", str(out), "--repeat", "1", "--quiet", *args],
                       check=True, capture_output=True, text=True)
        with open(os.path.join(out, "summary.json")) as f:
            return json.load(f)

    return run
