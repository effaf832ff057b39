"""`pip install .` for the Python module `ddb` (docs/guide/python.md, "Build"): CMake configures the
project with only the module (no tests, apps or benchmarks), builds target ddb_python and
the built ddb*.so is installed as the extension. Offline, with the system's setuptools:

    python3 -m venv --system-site-packages /tmp/venv
    /tmp/venv/bin/pip install --no-build-isolation .
"""
import os
import re
import subprocess
import sys

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = os.path.dirname(os.path.abspath(__file__))


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        build = os.path.abspath(os.path.join(self.build_temp, "cmake"))
        subprocess.run(["cmake", "-S", ROOT, "-B", build, "-DCMAKE_BUILD_TYPE=Release",
                        f"-DPython3_EXECUTABLE={sys.executable}", "-DDDB_BUILD_PYTHON=ON",
                        "-DDDB_BUILD_TESTS=OFF", "-DDDB_BUILD_APPS=OFF", "-DDDB_BUILD_BENCH=OFF"],
                       check=True)
        subprocess.run(["cmake", "--build", build, "--target", "ddb_python",
                        "-j", os.environ.get("DDB_BUILD_JOBS", "2")], check=True)
        built = os.path.join(build, "python", os.path.basename(self.get_ext_filename(ext.name)))
        target = self.get_ext_fullpath(ext.name)
        os.makedirs(os.path.dirname(target), exist_ok=True)
        self.copy_file(built, target)


with open(os.path.join(ROOT, "CMakeLists.txt")) as f:
    VERSION = re.search(r"project\(ddb VERSION (\S+)", f.read()).group(1)

setup(name="ddb", version=VERSION,
      description="Discrete double-bracket integrators for Lie-Poisson systems",
      ext_modules=[Extension("ddb", sources=[])], cmdclass={"build_ext": CMakeBuild},
      zip_safe=False)
