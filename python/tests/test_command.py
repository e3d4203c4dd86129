"""The mdrsim command installed with the package: the console script, python -m mdrsim, and the
wheel's shared-library needs."""

import os
import shutil
import subprocess
import sys
import sysconfig
from importlib import metadata
from pathlib import Path

import pytest

import mdrsim
from mdrsim import _command

# What any Linux program built by g++ links: the C and C++ runtimes. fmt, spdlog and toml++ are
# compiled in (python/header_only_deps.cmake), so the wheel runs without Debian's -dev packages.
RUNTIME = {"libstdc++.so.6", "libm.so.6", "libgcc_s.so.1", "libc.so.6", "ld-linux-x86-64.so.2"}


def installed():
    try:
        return metadata.distribution("mdrsim")
    except metadata.PackageNotFoundError:
        return None


def console_script():
    """The `mdrsim` script pip wrote beside this interpreter (a venv's bin/)."""
    if installed() is None:
        pytest.skip("mdrsim is not installed (PYTHONPATH to a build tree): no console script")
    for folder in (sysconfig.get_path("scripts"), Path(sys.executable).parent):
        script = Path(folder) / "mdrsim"
        if script.is_file():
            return script
    pytest.fail("mdrsim is installed but its console script is not beside the interpreter")


def test_the_package_declares_the_console_script():
    if installed() is None:
        pytest.skip("mdrsim is not installed (PYTHONPATH to a build tree)")
    (entry,) = [e for e in installed().entry_points
                if e.group == "console_scripts" and e.name == "mdrsim"]
    assert entry.value == "mdrsim._command:main"


def test_the_console_script_runs_the_command():
    out = subprocess.run([str(console_script()), "--version"], capture_output=True, text=True,
                         check=True)
    assert out.stdout == f"mdrsim {mdrsim.__version__}\n"
    assert out.stderr == ""


def test_the_console_script_passes_on_the_exit_code_and_messages(tmp_path):
    # Bad input: the command's exit 2 and its one-line message, not a Python traceback.
    missing = tmp_path / "missing.toml"
    out = subprocess.run([str(console_script()), "run", str(missing)], capture_output=True,
                         text=True)
    assert out.returncode == 2
    assert out.stderr == f"{missing}: cannot read the scene file (no such file or directory)\n"


def test_python_m_mdrsim_is_the_command(cli):
    # The command in the package is the one the build makes: same version, same JSON.
    assert _command.COMMAND.is_file() and os.access(_command.COMMAND, os.X_OK)
    out = subprocess.run([sys.executable, "-m", "mdrsim", "--version"], capture_output=True,
                         text=True, check=True)
    assert out.stdout == f"mdrsim {mdrsim.__version__}\n"
    scene = "scenes/fig2_fixed_load.toml"
    ours = subprocess.run([sys.executable, "-m", "mdrsim", "run", scene, "--set",
                           "discretization.springs=2000", "--log-level", "off", "--json", "-"],
                          capture_output=True, text=True, check=True).stdout
    theirs = subprocess.run([cli, "run", scene, "--set", "discretization.springs=2000",
                             "--log-level", "off", "--json", "-"],
                            capture_output=True, text=True, check=True).stdout
    strip = [line for line in ours.splitlines() if "wall_time_s" not in line]
    assert strip == [line for line in theirs.splitlines() if "wall_time_s" not in line]


def needed_libraries(path):
    readelf = shutil.which("readelf")
    if readelf is None:
        pytest.skip("readelf (binutils) is not installed")
    out = subprocess.run([readelf, "-d", str(path)], capture_output=True, text=True,
                         check=True).stdout
    return {line.split("[", 1)[1].split("]", 1)[0] for line in out.splitlines()
            if "(NEEDED)" in line}


# The command's `fit` and mdrsim.afm read measured files through Debian's libzip and HDF5
# (docs/afm.md): shared libraries both need at run time.
READERS = {"libzip.so.4", "libhdf5_serial.so.103"}


@pytest.mark.parametrize("part", ["extension", "command"])
def test_the_wheel_needs_only_the_runtimes_and_the_readers(part):
    path = Path(mdrsim._core.__file__) if part == "extension" else _command.COMMAND
    assert needed_libraries(path) <= RUNTIME | READERS
