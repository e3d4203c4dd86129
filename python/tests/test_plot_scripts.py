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


def distance_to_lines(x, y, lines):
    """The distance from (x, y) to the nearest segment of any of `lines` (Line2D polylines)."""
    best = float("inf")
    for line in lines:
        xs, ys = line.get_xdata(), line.get_ydata()
        for x0, y0, x1, y1 in zip(xs[:-1], ys[:-1], xs[1:], ys[1:]):
            dx, dy = x1 - x0, y1 - y0
            t = 0.0 if dx == dy == 0 else max(0.0, min(1.0, ((x - x0) * dx + (y - y0) * dy)
                                                         / (dx * dx + dy * dy)))
            best = min(best, ((x0 + t * dx - x) ** 2 + (y0 + t * dy - y) ** 2) ** 0.5)
    return best


def drawn(ax, prefix):
    return [line for line in ax.get_lines() if line.get_label().startswith(prefix)]


def curves(ax):
    """The solid lines without markers: the closed forms (and the zero lines)."""
    return [line for line in ax.get_lines()
            if line.get_marker() in ("None", None, "") and line.get_linestyle() == "-"
            and len(line.get_xdata()) > 2]


def test_paper_figures_draw_the_run_at_its_own_scales(cli, tmp_path, capsys):
    import plot_paper_figures as paper

    # nu = 0.3 changes E* (E/(1 - nu^2)) and G*/E* (eq. 9), so F0's companions a0, d0 and the
    # closed forms of Fig. 3a: read from the run's JSON, not the scene file.
    nu = ["--set", "material.poisson_ratio=0.3"]
    run(cli, "scenes/fig2_fixed_load.toml", *nu, "--trajectory", str(tmp_path / "fig2_fixed_load.csv"),
        "--json", str(tmp_path / "fig2_fixed_load.json"))
    fig = paper.figure_fig2(str(tmp_path), "fixed_load", "b")
    ax = fig.axes[0]
    (points,) = drawn(ax, "simulation")
    (jkr,) = drawn(ax, "analytic")
    assert len(points.get_xdata()) > 100
    # The row's detachments lie on the JKR branch within O(1/N) of F0 and d0 (rows of 20000
    # springs: 2.6e-4 here); with the scene file's nu = 0 scales they were 0.26 off.
    far = max(distance_to_lines(x, y, [jkr]) for x, y in zip(points.get_xdata(), points.get_ydata()))
    assert far < 2e-3
    plt.close(fig)

    vary = ["--vary", "loading.tangential.displacement=0:9e-6:9", "--log-level", "off"]
    for control in ("fixed_grips", "fixed_load"):
        scene = f"scenes/fig3a_{control}.toml"
        subprocess.run([cli, "sweep", scene, *vary, *nu, "--csv", str(tmp_path / f"fig3a_{control}.csv")],
                       check=True)
        run(cli, scene, *nu, "--json", str(tmp_path / f"fig3a_{control}.json"))
    fg, fl = paper.Sweep(str(tmp_path), "fig3a_fixed_grips"), paper.Sweep(str(tmp_path), "fig3a_fixed_load")
    assert fg.run.gamma == pytest.approx((2 - 2 * 0.3) / (2 - 0.3), rel=1e-12)
    fig = paper.figure_fig3a(fg, fl)
    ax = fig.axes[0]
    assert "G^*/E^*=0.8235" in ax.get_title()
    lines = curves(ax)
    markers = [line for line in ax.get_lines() if line.get_label().startswith("fixed")]
    assert sum(len(m.get_xdata()) for m in markers) == 18
    # Every critical point on its closed form at the run's G*/E*, within the row's O(1/N)
    # (8.5e-7 here); the lines drawn at E* = G* missed them by up to 0.13 F0.
    for m in markers:
        for x, y in zip(m.get_xdata(), m.get_ydata()):
            assert distance_to_lines(x, y, lines) < 2e-3, (m.get_label(), x, y)
    plt.close(fig)


def test_paper_figures_draw_a_cone_without_the_parabolas_closed_forms(cli, tmp_path, capsys):
    import plot_paper_figures as paper

    shear = ["--set", 'loading.tangential={control="fixed-grips", displacement=0.0}',
             "--set", "discretization.springs=2000"]
    for control in ("fixed_grips", "fixed_load"):
        scene = f"scenes/cone_{control}.toml"
        run(cli, scene, "--set", "discretization.springs=2000",
            "--trajectory", str(tmp_path / f"fig2_{control}.csv"),
            "--json", str(tmp_path / f"fig2_{control}.json"))
        subprocess.run([cli, "sweep", scene, "--vary", "loading.tangential.displacement=0:1e-7:3",
                        *shear, "--log-level", "off", "--csv", str(tmp_path / f"fig3a_{control}.csv")],
                       check=True)
        run(cli, scene, *shear, "--json", str(tmp_path / f"fig3a_{control}.json"))
    assert paper.main(["--results", str(tmp_path)]) == 0
    out = capsys.readouterr().out
    assert "fig2_fixed_load.json: the paper's closed forms are a parabola's, not the cone's: left out" in out
    assert "fig_master_curve left out" in out
    for name in ("fig2a_fixed_grips", "fig2b_fixed_load", "fig3a", "fig3b"):
        assert (tmp_path / f"{name}.png").is_file()
    fig = paper.figure_fig2(str(tmp_path), "fixed_load", "b")
    assert drawn(fig.axes[0], "analytic") == []
    assert len(drawn(fig.axes[0], "simulation")[0].get_xdata()) > 100
    assert "Cone of 10 degrees" in fig.axes[0].get_title()
    plt.close(fig)


def test_rate_law_speed_reference_and_fast_asymptote():
    pytest.importorskip("scipy")
    import plot_rate_law_speed as speed

    # docs/rate_law.md's table (the C++ reference, tests/support/rate_law_front), 8 digits.
    assert speed.reference_peak(1.0, 0.5) == pytest.approx(-1.6207648, abs=1e-7)
    assert speed.reference_peak(100.0, 1.0) == pytest.approx(-8.1499919, abs=1e-7)
    assert speed.reference_peak(1e-4, 1.0) == pytest.approx(-1.0000492, abs=1e-7)
    # The fast asymptote's power: the ODE's ratio to it tends to 1 as 1 - C beta^(-n/(n+2)),
    # C below the script's bound and settling (n = 1: C -> 4/3).
    for n in (1.0, 0.5):
        ratios = [speed.reference_peak(beta, n) / speed.fast_asymptote(beta, n)
                  for beta in (1e6, 1e8, 1e10)]
        assert ratios == sorted(ratios) and ratios[-1] < 1.0
        coefficients = [(1.0 - r) * beta ** (n / (n + 2.0))
                        for r, beta in zip(ratios, (1e6, 1e8, 1e10))]
        assert all(c < speed.ASYMPTOTE_BOUND for c in coefficients)
        assert abs(coefficients[2] - coefficients[1]) < abs(coefficients[1] - coefficients[0])
    assert (1.0 - speed.reference_peak(1e10, 1.0) / speed.fast_asymptote(1e10, 1.0)) * 1e10 ** (
        1.0 / 3.0) == pytest.approx(4.0 / 3.0, abs=0.01)
