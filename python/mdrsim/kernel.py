"""`python -m mdrsim.kernel`: a Jupyter kernel named "mdrsim" that runs this very interpreter.

The example notebook (python/examples/fit_adhesion.ipynb) asks for the kernel "mdrsim".
Debian's own "python3" kernel runs /usr/bin/python3, which does not see a venv's packages:
there `import mdrsim` failed with "No module named 'mdrsim'". Run this once with the Python
mdrsim is installed in:

    .venv/bin/python -m mdrsim.kernel            # for this user (~/.local/share/jupyter)
    .venv/bin/python -m mdrsim.kernel --prefix P  # into P/share/jupyter/kernels/mdrsim
"""

import argparse
import json
import os
import subprocess
import sys
from pathlib import Path

NAME = "mdrsim"


def kernel_spec():
    """The kernel.json: this interpreter, and PYTHONPATH where mdrsim is found only through it
    (an uninstalled build)."""
    spec = {"argv": [sys.executable, "-Xfrozen_modules=off", "-m", "ipykernel_launcher", "-f",
                     "{connection_file}"],
            "display_name": f"Python (mdrsim, {sys.prefix})", "language": "python",
            "metadata": {"debugger": True}}
    env = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}
    bare = subprocess.run([sys.executable, "-c", "import mdrsim"], env=env, capture_output=True)
    if bare.returncode != 0:
        spec["env"] = {"PYTHONPATH": str(Path(__file__).resolve().parents[1])}
    return spec


def install(prefix=None):
    """Writes the kernel "mdrsim" for this user, or under `prefix`; returns its folder."""
    if prefix is None:
        from jupyter_core.paths import jupyter_data_dir
        base = Path(jupyter_data_dir())
    else:
        base = Path(prefix) / "share" / "jupyter"
    folder = base / "kernels" / NAME
    folder.mkdir(parents=True, exist_ok=True)
    (folder / "kernel.json").write_text(json.dumps(kernel_spec(), indent=1) + "\n")
    return folder


def main(argv=None):
    parser = argparse.ArgumentParser(prog="python -m mdrsim.kernel", description=__doc__.split(
        "\n\n")[0], formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--prefix", help="install under PREFIX/share/jupyter (default: the "
                                         "user's Jupyter folder)")
    args = parser.parse_args(argv)
    try:
        import ipykernel  # noqa: F401
    except ImportError:
        print("python -m mdrsim.kernel: ipykernel is not installed for this Python "
              "(Debian: apt-get install python3-ipykernel)", file=sys.stderr)
        return 2
    folder = install(args.prefix)
    print(f"installed the Jupyter kernel '{NAME}' ({sys.executable}) in {folder}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
