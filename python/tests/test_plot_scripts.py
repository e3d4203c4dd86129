"""The plot scripts (scripts/plot_*.py) on runs of the mdrsim command: what each figure draws,
read from its matplotlib objects rather than its pixels."""

import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "scripts"))

matplotlib = pytest.importorskip("matplotlib")
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def run(cli, scene, *flags):
    subprocess.run([cli, "run", scene, "--log-level", "off", *flags], check=True)


def test_plot_program_titles_with_the_scene_and_labels_in_readable_units(cli, tmp_path):
    import plot_program

    trajectory, result = tmp_path / "cycle.csv", tmp_path / "cycle.json"
    run(cli, "scenes/programs/fretting_parabola.toml", "--trajectory", str(trajectory),
        "--json", str(result))
    args = plot_program.argparse.Namespace(title=None, json=str(result),
                                           trajectory=str(trajectory))
    title = plot_program.title_of(args)
    # The scene's own title, not where its file lay.
    assert title.startswith("Fretting cycle of a sphere") and "/" not in title
    assert plot_program.title_of(plot_program.argparse.Namespace(
        title=None, json=None, trajectory=str(trajectory))) == "cycle.csv"
    fig = plot_program.figure(str(trajectory), title)
    fig.canvas.draw()
    normal, tangential = fig.axes
    # R = 1 cm: depths of micrometres, forces of millinewtons (normal) and hundreds of
    # micronewtons (tangential); each axis in the prefix that puts its largest value in [1, 1000).
    assert normal.get_xlabel() == "indentation d [\u00b5m]"
    assert normal.get_ylabel() == "normal force F [mN]"
    assert tangential.get_xlabel() == "tangential displacement u_x [\u00b5m]"
    assert tangential.get_ylabel() == "tangential force F_x [\u00b5N]"
    for ax in fig.axes:
        for axis in (ax.xaxis, ax.yaxis):
            assert axis.get_offset_text().get_text() == ""
        for line in ax.get_lines():
            xs, ys = line.get_xdata(), line.get_ydata()
            if len(xs):
                assert max(abs(v) for v in xs) < 1000.0 and max(abs(v) for v in ys) < 1000.0
    # The amplitude u_m = 1 um: the loop spans -1 .. 1 in the unit shown.
    xs = [v for line in tangential.get_lines() for v in line.get_xdata()]
    assert max(xs) == pytest.approx(1.0, rel=1e-9) and min(xs) == pytest.approx(-1.0, rel=1e-9)
    plt.close(fig)
