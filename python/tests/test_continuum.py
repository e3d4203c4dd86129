"""method="continuum" from Python: mdrsim.run, Scene.with_method, sweeps, and the sampled branch,
against the paper's closed forms (scripts/paper_reference.py, which shares no code with the
engine)."""

import math
import subprocess
import sys

import numpy as np
import pytest

import mdrsim

from conftest import ROOT

sys.path.insert(0, str(ROOT / "scripts"))
import paper_reference as ref  # noqa: E402

FIG2 = "scenes/fig2_fixed_load.toml"
FIG3A = "scenes/fig3a_fixed_grips.toml"
F0 = 1.5 * math.pi * 0.01 * 0.05  # paper eq. 17: R = 1 cm, dgamma = 0.05 J/m^2
D0 = 2.2614848269449475e-6        # paper eq. 17 for the same scenes [m]


def test_run_with_method_continuum_gives_the_closed_form_to_1e10():
    result = mdrsim.run(FIG2, method="continuum", trajectory=False)
    assert result.status == "instability"
    # -F0 (eq. 19's minimum); the route's rtol is 1e-10 and its estimate below it.
    assert result.critical.normal_force / F0 == pytest.approx(-1.0, rel=1e-10)
    out = result.to_dict()
    assert out["method"] == "continuum" and out["resolution"] == {"route": "continuum"}
    assert "springs" not in out and out["accuracy"]["rtol_met"] is True
    grips = mdrsim.run("scenes/fig2_fixed_grips.toml", method="continuum", trajectory=False)
    assert grips.critical.normal_force / F0 == pytest.approx(-5.0 / 9.0, rel=1e-10)  # eq. 33
    assert grips.peak.normal_force / F0 == pytest.approx(-1.0, rel=1e-10)


def test_with_method_drops_the_rows_keys_and_keeps_rtol():
    scene = mdrsim.Scene.from_file(FIG2)  # springs = 10000, method = "event"
    assert scene.method == "event"
    continuum = scene.with_method("continuum")
    assert continuum.method == "continuum"
    assert continuum.to_dict()["discretization"] == {}
    assert "continuum route" in repr(continuum) and "springs" not in repr(continuum)
    tight = scene.with_method("continuum", rtol=1e-8)
    assert tight.to_dict()["discretization"] == {"rtol": 1e-8}
    back = tight.with_method("event")
    assert back.method == "event" and back.to_dict()["solver"] == {"method": "event"}
    with pytest.raises(mdrsim.SceneError, match="unknown name 'springs'"):
        scene.with_method("springs")


def test_rtol_without_a_method_takes_the_continuum_route():
    scene = mdrsim.Scene.from_file(FIG3A).set("discretization", {"rtol": 1e-10})
    assert scene.method == "continuum"  # fig3a names no [solver] method
    result = mdrsim.run(scene, trajectory=False)
    assert result.to_dict()["accuracy"]["route"] == "continuum"
    u = 2.2614848269449475e-6 / D0  # the scene's u = d0
    assert result.critical.normal_force / F0 == pytest.approx(
        ref.critical("fixed-grips", u)["Fz"], abs=1e-9)  # the reference's own root: 1e-12
    # With method = "event" named, rtol stays on the row.
    row = scene.set("solver", {"method": "event"}).set("discretization", {"rtol": 1e-3})
    assert row.method == "event"
    assert mdrsim.run(row, trajectory=False).to_dict()["resolution"]["route"] != "continuum"


def test_a_normal_program_runs_on_the_continuum_route_and_a_shear_is_refused():
    cycle = mdrsim.Scene.from_file("scenes/programs/jkr_cycle_reversible.toml")
    result = mdrsim.run(cycle.with_method("continuum"), trajectory=False)
    assert result.to_dict()["accuracy"]["route"] == "continuum"
    # The fixed-grips fold of the JKR branch: F_c = -5/9 F0 (the scene's comment).
    assert result.critical.normal_force / F0 == pytest.approx(-5.0 / 9.0, rel=1e-9)
    with pytest.raises(mdrsim.SceneError, match="shears until separation"):
        mdrsim.Scene.from_file("scenes/programs/shear_ramp_fixed_grips.toml").with_method(
            "continuum")


def test_a_shear_the_route_cannot_follow_is_refused_by_the_run():
    # Known only once the route runs: the tangential load lets the glue go as it is applied
    # (docs/continuum.md "What it refuses"). The row follows it to a shear-off.
    table = {
        "material": {"youngs_modulus": 1e6, "poisson_ratio": 0.0, "work_of_adhesion": 0.05},
        "profile": {"type": "parabolic", "radius": 0.01},
        "loading": {"stage": [
            {"name": "preload", "normal": {"control": "fixed-grips", "to": 2.713781792333937e-5}},
            {"name": "tangential", "normal": {"control": "fixed-grips"},
             "tangential": {"control": "fixed-grips", "to": 3e-5}},
            {"name": "pull-off", "normal": {"by": -1e-6}, "until": "separation"},
        ]},
    }
    scene = mdrsim.Scene.from_dict(table)
    with pytest.raises(mdrsim.SceneError,
                       match=r"solver\.method: stage 'tangential': the tangential load lets the "
                             r"glue go as it is applied"):
        mdrsim.run(scene.with_method("continuum"), trajectory=False)
    assert mdrsim.run(scene, trajectory=False).status == "shear-off"


def test_samples_are_the_branch_evenly_in_the_contact_radius():
    scene = mdrsim.Scene.from_file(FIG2).with_method("continuum")
    result = mdrsim.run(scene, samples=1000)
    t = result.trajectory
    rows = [i for i, e in enumerate(t["event"]) if e == "sample"]
    assert len(rows) == 1000
    a = t["contact_radius"][rows]
    steps = np.diff(a)
    assert np.all(steps < 0) and np.allclose(steps, steps[0], rtol=1e-9)
    # From the glued radius 2 a0 down to the critical point a0 (fixed load), on JKR's branch
    # (eq. 18, in units of F0 and a0, by the reference).
    a0 = result.critical.contact_radius
    assert a[0] / a0 == pytest.approx(2.0, rel=1e-9) and a[-1] == a0
    for i in (0, 333, 999):
        f = t["normal_force"][rows[i]] / F0
        assert f == pytest.approx(ref.jkr_force(a[i] / a0), abs=1e-9)
    default = mdrsim.run(scene).trajectory
    assert sum(e == "sample" for e in default["event"]) == mdrsim.SAMPLES
    assert mdrsim.run(scene, trajectory=False).trajectory is None
    with pytest.raises(ValueError, match="samples=-1"):
        mdrsim.run(scene, samples=-1)


def test_sweep_with_method_continuum_matches_the_closed_forms():
    grid = {"loading.tangential.displacement": [0.0, 2.0 * D0, 4.0 * D0]}
    swept = mdrsim.sweep(FIG3A, grid, method="continuum")
    assert len(swept) == 3
    for values, u in zip(swept.rows, (0.0, 2.0, 4.0)):
        exact = ref.critical("fixed-grips", u)
        assert values["status"] == "instability"
        assert values["normal_force"] / F0 == pytest.approx(exact["Fz"], abs=1e-9)
        assert values["tangential_force"] / F0 == pytest.approx(exact["Fx"], abs=1e-9)


def test_maugis_keys_pass_through_a_python_built_scene():
    # Maugis' parabola (R = 1 cm, E* = 1 MPa, dgamma = 0.05 J/m^2) at lambda = 1, built as a dict:
    # the fixed-load pull-off is Maugis' P = -1.6007349 pi dgamma R (docs/maugis.md, 1e-6).
    scene = mdrsim.Scene.from_dict({
        "material": {"effective_modulus": 1.0e6, "work_of_adhesion": 0.05,
                     "maugis_parameter": 1.0},
        "profile": {"type": "parabolic", "radius": 0.01},
        "loading": {"preload": {"contact_radius": 6.8e-4},
                    "normal": {"control": "fixed-load"}}})
    result = mdrsim.run(scene, trajectory=False)
    assert result.status == "instability"
    force = math.pi * 0.05 * 0.01
    assert result.critical.normal_force / force == pytest.approx(-1.6007349, abs=1e-6)
    assert result.critical.cohesive_radius > result.critical.contact_radius > 0.0
    assert result.dimensionless["maugis_parameter"] == pytest.approx(1.0, rel=1e-14)
    assert result.maugis_parameter == pytest.approx(1.0, rel=1e-14)
    assert result.to_dict()["dimensionless"]["maugis_parameter"] == pytest.approx(1.0, rel=1e-14)
    # The same scene with the keys' value changed through with_values.
    stress = scene.with_values({"material.maugis_parameter": 2.0})
    assert mdrsim.run(stress, trajectory=False).maugis_parameter == pytest.approx(2.0, rel=1e-14)
    # Without the keys: no zone in the states.
    assert mdrsim.run(FIG2, method="continuum", trajectory=False).critical.cohesive_radius is None


@pytest.mark.parametrize("path, method", [
    ("scenes/maugis/maugis_parabola.toml", None),      # continuum shorthand, with samples
    ("scenes/maugis/maugis_parabola.toml", "event"),   # the spring row's let-gos
    ("scenes/maugis/maugis_cycle.toml", None),         # a program on the continuum route
])
def test_maugis_trajectories_carry_the_cohesive_radius_as_the_csv(cli, tmp_path, path, method):
    # The arrays gain cohesive_radius as the CLI's trajectory CSV gains its column: the same
    # numbers row by row (both print shortest round-trip doubles), and c >= a on every row.
    scene = mdrsim.Scene.from_file(ROOT / path)
    if method:
        scene = scene.with_method(method)
    result = mdrsim.run(scene, samples=50)
    t = result.trajectory
    c = t["cohesive_radius"]
    assert c.dtype == np.float64 and len(c) == len(t["event"])
    assert np.all(c >= t["contact_radius"])
    assert np.any(c > 0.0)
    if result.critical is not None:
        rows = [i for i, e in enumerate(t["event"]) if e == "instability"]
        assert rows and c[rows[-1]] == result.critical.cohesive_radius
    # The CLI's CSV of the same scene.
    scene_file = tmp_path / "scene.toml"
    scene_file.write_text((ROOT / path).read_text() + (
        '\n[solver]\nmethod = "event"\n' if method else ""))
    csv = tmp_path / "trajectory.csv"
    subprocess.run([cli, "run", str(scene_file), "--trajectory", str(csv), "--samples", "50"],
                   check=True, capture_output=True)
    lines = csv.read_text().splitlines()
    header = lines[0].split(",")
    column = header.index("cohesive_radius")
    from_csv = np.array([float(line.split(",")[column]) for line in lines[1:]])
    assert np.array_equal(from_csv, c)


def test_without_the_maugis_keys_the_arrays_have_no_cohesive_radius():
    assert "cohesive_radius" not in mdrsim.run(FIG2, method="continuum", samples=10).trajectory
