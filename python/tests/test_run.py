"""mdrsim.run and its Result: the same numbers as `mdrsim run`, stages, jumps, work, outputs."""

import csv
import json
import math
import pickle
import subprocess

import pytest

import mdrsim

FIG2 = "scenes/fig2_fixed_load.toml"
F0 = 1.5 * math.pi * 0.01 * 0.05  # paper eq. 17: R = 1 cm, dgamma = 0.05 J/m^2
FIELDS = ("normal_force", "tangential_force", "contact_radius", "indentation",
          "tangential_displacement")


def test_critical_point_in_si_and_dimensionless():
    result = mdrsim.run(mdrsim.Scene.from_file(FIG2))
    assert result.status == "instability"
    c = result.critical
    # Fixed-load JKR pull-off at -F0 (paper eq. 19). The scene extrapolates rows of 5000, 10000
    # and 20000 springs (Richardson): 1e-8 F0 off here, within its error estimate.
    assert c.normal_force / F0 == pytest.approx(-1.0, abs=1e-7)
    accuracy = result.accuracy
    assert abs(c.normal_force + F0) <= accuracy["critical_error_estimate"]
    assert result.dimensionless == c.dimensionless
    for name, scale in zip(FIELDS, ("force", "force", "radius", "depth", "depth")):
        assert c.dimensionless[name] == getattr(c, name) / result.scales[scale]
    assert result.scales["force"] == pytest.approx(F0, rel=1e-15)
    assert result.peak.normal_force == c.normal_force  # fixed load: the peak is the jump
    assert result.springs == 20000  # the finest of the three rows
    assert result.counts["events"] > 0 and result.wall_time_s > 0
    assert result.warnings == [] and result.tangential_strength is None
    # A plain row estimates nothing.
    plain = mdrsim.run(mdrsim.Scene.from_file(FIG2).with_values(
        {"discretization.extrapolation": "none", "discretization.springs": 1000}), trajectory=False)
    assert plain.accuracy is None
    assert "instability" in repr(result)


def test_stop_reason_is_a_step_limits_alone():
    stopped = mdrsim.run(mdrsim.Scene.from_file(FIG2).with_values(
        {"discretization.extrapolation": "none", "discretization.springs": 200,
         "solver": {"method": "stepping", "max_steps": 5}}), trajectory=False)
    assert stopped.status == "step-limit"
    assert stopped.stop_reason == "max-steps"
    assert stopped.to_dict()["stop_reason"] == "max-steps"
    assert pickle.loads(pickle.dumps(stopped)).stop_reason == "max-steps"
    plain = mdrsim.run(FIG2, trajectory=False)
    assert plain.status == "instability" and plain.stop_reason is None
    assert "stop_reason" not in plain.to_dict()


def test_same_json_as_the_command(cli):
    result = mdrsim.run(mdrsim.Scene.from_file(FIG2).with_values({"discretization.springs": 3000}))
    done = subprocess.run([cli, "run", FIG2, "--set", "discretization.springs=3000", "--json", "-",
                           "--log-level", "off"], capture_output=True, text=True, check=True)
    ours, theirs = result.to_dict(), json.loads(done.stdout)
    ours.pop("wall_time_s"), theirs.pop("wall_time_s")
    assert ours == theirs


def test_program_stages_jumps_and_work():
    result = mdrsim.run(mdrsim.Scene.from_file("scenes/programs/jkr_cycle_glue_on_touch.toml"))
    assert [s.name for s in result.stages] == ["approach", "retract"]
    jump = result.jumps[-1]
    assert (jump.kind, jump.stage, jump.after.springs_in_contact) == ("out", "retract", 0)
    assert jump.springs == -jump.critical.springs_in_contact
    # The cycle's dissipated energy (scene comment): 2.184896 F0 d0 = 1.1642e-8 J; O(1/N).
    assert result.work.normal == pytest.approx(1.1642e-8, rel=2e-3)
    assert result.work.normal == pytest.approx(sum(s.work.normal for s in result.stages),
                                               rel=1e-12)
    assert result.critical == jump.critical
    as_dict = result.to_dict()
    assert as_dict["stages"][0]["end"]["normal_force"] == result.stages[0].end.normal_force
    assert as_dict["work"]["normal"] == result.work.normal


def test_shear_off_reports_tangential_strength_and_no_critical():
    scene = mdrsim.Scene.from_file("scenes/fig3a_fixed_grips.toml").with_values(
        {"loading.tangential.displacement": 2e-5, "discretization.springs": 1000})
    result = mdrsim.run(scene)
    assert result.status == "shear-off"
    assert result.critical is None and result.dimensionless is None
    assert result.tangential_strength > 0


def test_trajectory_matches_the_csv(cli, tmp_path):
    scene = mdrsim.Scene.from_file("scenes/fig3a_fixed_load.toml").with_values(
        {"discretization.springs": 500})
    t = mdrsim.run(scene).trajectory
    path = tmp_path / "t.csv"
    subprocess.run([cli, "run", "scenes/fig3a_fixed_load.toml", "--set",
                    "discretization.springs=500", "--trajectory", str(path), "--log-level", "off"],
                   check=True, capture_output=True)
    with open(path) as f:
        rows = list(csv.DictReader(f))
    assert len(rows) == len(t["event"])
    assert [r["stage"] for r in rows] == t["stage"]
    assert [r["event"] for r in rows] == t["event"]
    assert [r["in_cascade"] == "1" for r in rows] == t["in_cascade"].tolist()
    for name in FIELDS + ("springs_in_contact",):
        assert [float(r[name]) for r in rows] == t[name].tolist(), name


def test_without_trajectory():
    result = mdrsim.run(mdrsim.Scene.from_file(FIG2), trajectory=False)
    assert result.trajectory is None
    pytest.importorskip("pandas")
    with pytest.raises(ValueError, match="no trajectory"):
        result.to_dataframe()


def test_run_takes_a_path_or_a_dict():
    assert mdrsim.run(FIG2, trajectory=False).critical == mdrsim.run(
        mdrsim.Scene.from_file(FIG2), trajectory=False).critical


def test_warnings_reach_python():
    scene = mdrsim.Scene.from_file(FIG2).with_values(
        {"discretization.springs": 100, "discretization.extrapolation": "none"})
    with pytest.warns(mdrsim.RunWarning, match="springs in contact"):
        result = mdrsim.run(scene)
    assert len(result.warnings) == 1


def test_to_dataframe():
    pandas = pytest.importorskip("pandas")
    frame = mdrsim.run(mdrsim.Scene.from_file(FIG2).with_values(
        {"discretization.springs": 200})).to_dataframe()
    assert isinstance(frame, pandas.DataFrame)
    assert list(frame.columns[:3]) == ["stage", "event", "in_cascade"]
    assert frame["event"].iloc[0] == "preload"


def test_plot_draws_the_path_jumps_and_critical_point(tmp_path):
    matplotlib = pytest.importorskip("matplotlib")
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    result = mdrsim.run(mdrsim.Scene.from_file("scenes/programs/jkr_cycle_reversible.toml"))
    ax = result.plot()
    labels = [line.get_label() for line in ax.get_lines()]
    assert labels[0] == "path" and "jump" in labels
    assert any(label.startswith("critical: F = -0.55") for label in labels)
    ax.figure.savefig(tmp_path / "plot.png")
    assert (tmp_path / "plot.png").stat().st_size > 1000
    plt.close(ax.figure)


def test_plot_tangential_view_draws_fx_against_ux():
    matplotlib = pytest.importorskip("matplotlib")
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    result = mdrsim.run(mdrsim.Scene.from_file("scenes/programs/shear_ramp_fixed_grips.toml"))
    scales = result.scales
    ax = result.plot(view="tangential")
    assert ax.get_xlabel() == "tangential displacement u_x / d0"
    assert ax.get_ylabel() == "tangential force F_x / F0"
    path = ax.get_lines()[0]
    t = result.trajectory
    keep = ~t["in_cascade"]
    assert list(path.get_xdata()) == list(t["tangential_displacement"][keep] / scales["depth"])
    assert list(path.get_ydata()) == list(t["tangential_force"][keep] / scales["force"])
    c = result.critical
    marker = [line for line in ax.get_lines() if line.get_label().startswith("critical")][0]
    assert marker.get_label() == f"critical: F_x = {c.tangential_force / scales['force']:.4g} F0"
    assert list(marker.get_xdata()) == [c.tangential_displacement / scales["depth"]]
    plt.close(ax.figure)
    with pytest.raises(ValueError, match="unknown view 'shear' \\(known: normal, tangential\\)"):
        result.plot(view="shear")
    plt.close("all")


def test_set_log_level():
    mdrsim.set_log_level("warn")
    mdrsim.set_log_level("off")
    with pytest.raises(ValueError, match="unknown log level 'loud'"):
        mdrsim.set_log_level("loud")


def test_plot_frames_the_path_not_the_jumps_far_end():
    matplotlib = pytest.importorskip("matplotlib")
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    result = mdrsim.run(mdrsim.Scene.from_file(FIG2))
    ax = result.plot()
    # The path runs from the preload (d = 12 d0, F = 8.0 F0: the scene's 2 a0, eq. 18) to the
    # critical point (d = -d0, F = -F0, eq. 19). Under the fixed load the indenter then
    # separates: the jump has no state after it (it once landed at d = -1e4 d0, the last
    # spring's reach, and the frame spanned -10,502 to 513 d0), and nothing is drawn past it.
    lo, hi = ax.get_xlim()
    assert -2.0 < lo < -1.0 and 12.0 < hi < 13.0
    lo, hi = ax.get_ylim()
    assert -1.6 < lo < -1.0 and 8.0 < hi < 8.6
    assert ax.get_xlabel() == "indentation d / d0" and ax.get_ylabel() == "normal force F / F0"
    notes = [child.get_text() for child in ax.texts]
    assert notes == []
    assert result.jumps[0].after is None
    assert ax.get_title().startswith("Fig. 2: JKR pull-off, fixed-load\ninstability")
    plt.close(ax.figure)
