"""The fitting example (python/examples): the script and the notebook recover known parameters."""

import json
import re
import subprocess
import sys
from pathlib import Path

import pytest

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"
# Printed tolerances (fit_adhesion.py: about 4 standard errors at 1 % noise).
TOLERANCE = {"work_of_adhesion": 0.02, "lambda": 0.035, "effective_modulus": 0.015}
RELATIVE = {"work_of_adhesion": True, "lambda": False, "effective_modulus": True}
ROW = re.compile(r"^\s+(\w+)\s+(\S+)\s+(\S+)\s+\S+\s+\S+\s+(\S+)%?$")


def test_script_recovers_the_parameters(tmp_path):
    pytest.importorskip("scipy", reason="the fitting example needs scipy (python3-scipy)")
    png = tmp_path / "fit.png"
    run = subprocess.run([sys.executable, str(EXAMPLES / "fit_adhesion.py"), "--plot", str(png)],
                         cwd=tmp_path, capture_output=True, text=True, timeout=120)
    assert run.returncode == 0, run.stdout + run.stderr
    assert run.stdout.rstrip().endswith("every parameter within tolerance"), run.stdout
    # The table itself, checked here too: (a) two rows, (b) two rows, each within tolerance.
    rows = [ROW.match(line) for line in run.stdout.splitlines()]
    rows = [m.groups() for m in rows if m and m.group(1) in TOLERANCE]
    assert [r[0] for r in rows] == ["work_of_adhesion", "lambda",
                                    "work_of_adhesion", "effective_modulus"], run.stdout
    for name, true, fitted, tolerance in rows:
        true, fitted = float(true), float(fitted)
        error = fitted / true - 1 if RELATIVE[name] else fitted - true
        assert abs(error) <= TOLERANCE[name], (name, true, fitted)
        # the tolerance printed is the one checked (percent for the relative ones)
        assert float(tolerance.rstrip("%")) == pytest.approx(
            TOLERANCE[name] * (100 if RELATIVE[name] else 1)), (name, tolerance)
    assert png.stat().st_size > 10_000  # the figure was drawn


def test_notebook_runs_and_recovers_the_parameters(tmp_path, monkeypatch):
    pytest.importorskip("scipy", reason="the fitting example needs scipy (python3-scipy)")
    nbformat = pytest.importorskip("nbformat", reason="needs nbformat (python3-nbformat)")
    nbclient = pytest.importorskip("nbclient", reason="needs nbclient (python3-nbclient)")
    pytest.importorskip("ipykernel", reason="needs ipykernel (python3-ipykernel)")
    # A kernel of this very interpreter (the venv where mdrsim is installed): Debian's own
    # python3 kernelspec runs /usr/bin/python3, which does not see the venv's packages.
    spec = tmp_path / "jupyter" / "kernels" / "mdrsim-test"
    spec.mkdir(parents=True)
    (spec / "kernel.json").write_text(json.dumps({
        "argv": [sys.executable, "-Xfrozen_modules=off", "-m", "ipykernel_launcher",
                 "-f", "{connection_file}"],
        "display_name": "mdrsim test", "language": "python"}))
    monkeypatch.setenv("JUPYTER_PATH", str(tmp_path / "jupyter"))
    monkeypatch.setenv("JUPYTER_RUNTIME_DIR", str(tmp_path / "runtime"))
    monkeypatch.setenv("IPYTHONDIR", str(tmp_path / "ipython"))
    monkeypatch.delenv("MPLBACKEND", raising=False)

    nb = nbformat.read(EXAMPLES / "fit_adhesion.ipynb", as_version=4)
    assert all(not c.get("outputs") for c in nb.cells if c.cell_type == "code"), \
        "the notebook is stored with its outputs cleared"
    nb.cells.append(nbformat.v4.new_code_cell(
        "import sys, mdrsim; print(sys.executable); print(mdrsim.__file__)"))
    nbclient.NotebookClient(nb, timeout=120, kernel_name="mdrsim-test",
                            resources={"metadata": {"path": str(tmp_path)}}).execute()

    def text(cell):
        return "".join(o.get("text", "") for o in cell.outputs if o.output_type == "stream")

    import mdrsim
    assert text(nb.cells[-1]).split() == [sys.executable, mdrsim.__file__]
    assert text(nb.cells[-2]).strip() == "every parameter within tolerance"
    assert any("image/png" in o.get("data", {}) for c in nb.cells if c.cell_type == "code"
               for o in c.outputs), "the notebook draws its figure inline"


def test_notebook_runs_on_its_own_kernel(tmp_path, monkeypatch):
    """The notebook names the kernel "mdrsim", which `python -m mdrsim.kernel` makes for the
    Python mdrsim is installed in (Debian's "python3" kernel does not see a venv)."""
    pytest.importorskip("scipy", reason="the fitting example needs scipy (python3-scipy)")
    nbformat = pytest.importorskip("nbformat", reason="needs nbformat (python3-nbformat)")
    nbclient = pytest.importorskip("nbclient", reason="needs nbclient (python3-nbclient)")
    pytest.importorskip("ipykernel", reason="needs ipykernel (python3-ipykernel)")
    made = subprocess.run([sys.executable, "-m", "mdrsim.kernel", "--prefix", str(tmp_path)],
                          capture_output=True, text=True)
    assert made.returncode == 0, made.stderr
    spec = json.loads((tmp_path / "share/jupyter/kernels/mdrsim/kernel.json").read_text())
    assert spec["argv"][0] == sys.executable
    monkeypatch.setenv("JUPYTER_PATH", str(tmp_path / "share" / "jupyter"))
    monkeypatch.setenv("JUPYTER_RUNTIME_DIR", str(tmp_path / "runtime"))
    monkeypatch.setenv("IPYTHONDIR", str(tmp_path / "ipython"))
    monkeypatch.delenv("MPLBACKEND", raising=False)
    # A kernel must find mdrsim without the environment of the process that starts it.
    monkeypatch.delenv("PYTHONPATH", raising=False)

    nb = nbformat.read(EXAMPLES / "fit_adhesion.ipynb", as_version=4)
    assert nb.metadata.kernelspec.name == "mdrsim"
    nb.cells.append(nbformat.v4.new_code_cell("import sys, mdrsim; print(sys.executable)"))
    nbclient.NotebookClient(nb, timeout=120,
                            resources={"metadata": {"path": str(tmp_path)}}).execute()
    outputs = "".join(o.get("text", "") for o in nb.cells[-1].outputs)
    assert outputs.split() == [sys.executable]
