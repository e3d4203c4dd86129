"""Builds the Python module mdrsim: setuptools drives CMake (-DMDRSIM_PYTHON=ON), see docs/python.md "Installing"."""

import os
import re
import shutil
import subprocess
import sys
import time
from pathlib import Path

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = Path(__file__).resolve().parent
VERSION = re.search(r"project\(mdrsim VERSION ([0-9.]+)",
                    (ROOT / "CMakeLists.txt").read_text()).group(1)
# Kept between installs, so that a second install only rebuilds what changed.
BUILD = Path(os.environ.get("MDRSIM_PYTHON_BUILD_DIR", ROOT / "build-python-package"))
# The extension and the command it ships (python/CMakeLists.txt); no tests, no bench.
TARGET = "mdrsim_python_package"


def jobs():
    if os.environ.get("CMAKE_BUILD_PARALLEL_LEVEL"):
        return os.environ["CMAKE_BUILD_PARALLEL_LEVEL"]
    return str(len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity")
               else os.cpu_count() or 2)


def step(started, text):
    # pip shows these (and CMake's own lines) with -v; without it, only when the build fails.
    print(f"mdrsim build [{time.monotonic() - started:5.0f} s]: {text}", flush=True)


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        started = time.monotonic()
        cmake = BUILD / "cmake"
        step(started, f"configuring in {cmake} (CMake, Release)")
        subprocess.run(["cmake", "-S", str(ROOT), "-B", str(cmake), "-DCMAKE_BUILD_TYPE=Release",
                        "-DMDRSIM_PYTHON=ON", "-DMDRSIM_HEADER_ONLY_DEPS=ON",
                        "-DMDRSIM_BUILD_TESTS=OFF", "-DMDRSIM_BUILD_BENCH=OFF",
                        # About 8 sources per compiler call, the headers parsed once per
                        # batch: header-only fmt, spdlog and toml++ took the engine from 2.5 to
                        # 4.6 min of CPU file by file; in batches it takes 2.1.
                        "-DCMAKE_UNITY_BUILD=ON",
                        f"-DPython3_EXECUTABLE={sys.executable}"], check=True)
        step(started, f"compiling the engine, the extension and the command on {jobs()} jobs "
                      "(a first build: about 20 batches of sources, a few minutes)")
        subprocess.run(["cmake", "--build", str(cmake), "--target", TARGET, "-j", jobs()],
                       check=True)
        package = Path(self.get_ext_fullpath(ext.name)).parent
        package.mkdir(parents=True, exist_ok=True)
        built = next((cmake / "python" / "mdrsim").glob("_core*.so"))
        shutil.copyfile(built, self.get_ext_fullpath(ext.name))
        (package / "bin").mkdir(exist_ok=True)
        shutil.copy2(cmake / "python" / "mdrsim" / "bin" / "mdrsim", package / "bin" / "mdrsim")
        step(started, "built")


(BUILD / "egg-info").mkdir(parents=True, exist_ok=True)
setup(
    version=VERSION,
    packages=["mdrsim"],
    package_dir={"": "python"},
    package_data={"mdrsim": ["py.typed", "*.pyi"]},  # PEP 561 type stubs
    ext_modules=[Extension("mdrsim._core", sources=[])],
    cmdclass={"build_ext": CMakeBuild},
    zip_safe=False,
    options={"build": {"build_base": str(BUILD / "setuptools")},
             "egg_info": {"egg_base": str(BUILD / "egg-info")}},
)
