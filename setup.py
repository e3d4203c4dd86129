"""Builds the Python module mdrsim: setuptools drives CMake (-DMDRSIM_PYTHON=ON), see docs/python.md "Installing"."""

import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = Path(__file__).resolve().parent
VERSION = re.search(r"project\(mdrsim VERSION ([0-9.]+)",
                    (ROOT / "CMakeLists.txt").read_text()).group(1)
# Kept between installs, so that a second install only rebuilds what changed.
BUILD = Path(os.environ.get("MDRSIM_PYTHON_BUILD_DIR", ROOT / "build-python-package"))


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        cmake = BUILD / "cmake"
        subprocess.run(["cmake", "-S", str(ROOT), "-B", str(cmake), "-DCMAKE_BUILD_TYPE=Release",
                        "-DMDRSIM_PYTHON=ON", "-DMDRSIM_BUILD_TESTS=OFF",
                        f"-DPython3_EXECUTABLE={sys.executable}"], check=True)
        subprocess.run(["cmake", "--build", str(cmake), "--target", "mdrsim_python", "-j",
                        str(os.cpu_count() or 2)], check=True)
        built = next((cmake / "python" / "mdrsim").glob("_core*.so"))
        target = Path(self.get_ext_fullpath(ext.name))
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(built, target)


(BUILD / "egg-info").mkdir(parents=True, exist_ok=True)
setup(
    name="mdrsim",
    version=VERSION,
    description="Adhesive contact under normal and tangential loading (MDR spring model)",
    packages=["mdrsim"],
    package_dir={"": "python"},
    package_data={"mdrsim": ["py.typed", "*.pyi"]},  # PEP 561 type stubs
    ext_modules=[Extension("mdrsim._core", sources=[])],
    cmdclass={"build_ext": CMakeBuild},
    python_requires=">=3.9",
    install_requires=["numpy"],
    zip_safe=False,
    options={"build": {"build_base": str(BUILD / "setuptools")},
             "egg_info": {"egg_base": str(BUILD / "egg-info")}},
)
