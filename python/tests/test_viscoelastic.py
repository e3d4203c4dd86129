"""Time in Python: scenes with material.relaxation and detachment.front_speed_law built from
dicts and overrides, their Work's dissipations per stage and in total, and `time` in states,
stage ends and the trajectory (docs/viscoelastic.md, docs/rate_law.md)."""

import copy
import subprocess

import numpy as np
import pytest

import mdrsim

RATE_LAW = "scenes/viscoelastic/rate_law_parabola.toml"
LEE_RADOK = "scenes/viscoelastic/lee_radok_parabola.toml"

# scenes/viscoelastic/rate_law_parabola.toml as a dict: JKR's zero-force state of an elastic
# parabola (E* = 1 MPa, R = 1 cm, dgamma = 0.05 J/m^2), retracted at beta = 1, n = 1/2.
RATE_LAW_DICT = {
    "material": {"youngs_modulus": 1.0e6, "poisson_ratio": 0.0, "work_of_adhesion": 0.05,
                 "approach_work_of_adhesion": 0.05},
    "profile": {"type": "parabolic", "radius": 0.01},
    "detachment": {"front_speed_law": {"speed": 1.0e-6, "exponent": 0.5}},
    "loading": {"stage": [
        {"name": "approach", "normal": {"control": "fixed-grips", "to": 5.698584674971612e-06},
         "duration": 2.0},
        {"name": "retract", "normal": {"by": -1.0e-5}, "until": "separation",
         "speed": 1.7099759466766972e-08}]},
    "solver": {"method": "continuum"},
}

# scenes/viscoelastic/lee_radok_parabola.toml as a dict: a standard linear solid (E*_inf = 1
# MPa, E*_1 = 9 MPa, tau = 0.1 s) pressed at 0.1 mm/s for 0.2 s and withdrawn at that speed.
LEE_RADOK_DICT = {
    "material": {"effective_modulus": 1.0e6, "work_of_adhesion": 0.0,
                 "relaxation": [{"modulus": 9.0e6, "time": 0.1}]},
    "profile": {"type": "parabolic", "radius": 0.01},
    "loading": {"stage": [
        {"name": "press", "normal": {"control": "fixed-grips", "to": 2.0e-5}, "speed": 1.0e-4},
        {"name": "withdraw", "normal": {"control": "fixed-grips", "by": -2.0e-5},
         "until": "separation", "speed": 1.0e-4}]},
    "discretization": {"springs": 400},
    "solver": {"method": "event"},
}


def json_work(result):
    j = result.to_dict()
    return j["work"], [s["work"] for s in j["stages"]]


def assert_times(result):
    """`time` in every state the result reports, the stages' clocks chained, the trajectory's
    times in order from the first stage's start to the last stage's end."""
    assert result.critical.time is not None and result.peak.time is not None
    start = 0.0
    for stage in result.stages:
        assert stage.start_time == start and stage.end.time == stage.end_time
        assert stage.end_time >= stage.start_time
        start = stage.end_time
    time = result.trajectory["time"]
    assert time.dtype == np.float64 and len(time) == len(result.trajectory["normal_force"])
    # The continuum route's rows are its stage ends, then its samples along the walk
    # (engine/continuum/run_continuum_program: every stage stands before any sample).
    events = np.array(result.trajectory["event"])
    ends = time[events == "stage-end"]
    assert list(ends) == [stage.end_time for stage in result.stages]
    walk = time[events != "stage-end"]
    assert walk[0] == 0.0 and np.all(np.diff(walk) >= 0.0)
    assert walk[-1] == result.stages[-1].end_time
    assert result.to_dict()["critical"]["time"] == result.critical.time


def test_a_rate_law_scene_from_a_dict_is_the_file_and_names_its_front_dissipation():
    from_dict = mdrsim.run(mdrsim.Scene.from_dict(RATE_LAW_DICT))
    from_file = mdrsim.run(mdrsim.Scene.from_file(RATE_LAW))
    assert from_dict.to_dict()["peak_adhesion"] == from_file.to_dict()["peak_adhesion"]
    # The peak tension -1.6207648 F0 of the independent solution (docs/rate_law.md's table, 8
    # digits: the table's rounding).
    assert from_dict.peak.dimensionless["normal_force"] == pytest.approx(-1.6207648, abs=1e-7)
    total, stages = json_work(from_dict)
    assert from_dict.work.dissipated_at_front == total["dissipated_at_front"] > 0.0
    assert from_dict.dissipated_at_front == total["dissipated_at_front"]
    assert [s.work.dissipated_at_front for s in from_dict.stages] == [
        s["dissipated_at_front"] for s in stages]
    # The approach presses (the front advances: nothing dissipated there); the retraction is
    # the whole of it.
    assert from_dict.stages[0].work.dissipated_at_front == 0.0
    assert from_dict.stages[1].work.dissipated_at_front == total["dissipated_at_front"]
    # No relaxing bulk: no dashpots, and the JSON names none.
    assert from_dict.work.dissipated_by_bulk is None and from_dict.dissipated_by_bulk is None
    assert "dissipated_by_bulk" not in total
    assert_times(from_dict)


def test_a_relaxing_scene_from_a_dict_is_the_file_and_names_its_bulk_dissipation():
    from_dict = mdrsim.run(mdrsim.Scene.from_dict(LEE_RADOK_DICT))
    from_file = mdrsim.run(mdrsim.Scene.from_file(LEE_RADOK))
    assert from_dict.to_dict()["work"] == from_file.to_dict()["work"]
    total, stages = json_work(from_dict)
    assert from_dict.work.dissipated_by_bulk == total["dissipated_by_bulk"] > 0.0
    assert from_dict.dissipated_by_bulk == total["dissipated_by_bulk"]
    assert [s.work.dissipated_by_bulk for s in from_dict.stages] == [
        s["dissipated_by_bulk"] for s in stages]
    # docs/viscoelastic.md at 400 springs: the press dissipates 3.1961e-7 J, the withdrawal
    # 6.826e-8 J (its table's 5 and 4 digits).
    press, withdraw = from_dict.stages
    assert press.work.dissipated_by_bulk == pytest.approx(3.1961e-7, rel=2e-5)
    assert withdraw.work.dissipated_by_bulk == pytest.approx(6.826e-8, rel=1e-4)
    # The stages' sum is the total to rounding.
    assert press.work.dissipated_by_bulk + withdraw.work.dissipated_by_bulk == pytest.approx(
        from_dict.work.dissipated_by_bulk, rel=1e-14)
    # No rate law: the JSON names no front dissipation.
    assert from_dict.work.dissipated_at_front is None and "dissipated_at_front" not in total
    # No critical point (the contact peels off at zero force) and no peak tension: the times
    # are the stages' and the trajectory's.
    assert from_dict.status == "no-instability" and from_dict.critical is None
    time = from_dict.trajectory["time"]
    assert time[0] >= 0.0 and np.all(np.diff(time) >= 0.0)
    assert press.start_time == 0.0 and press.end_time == pytest.approx(0.2, rel=1e-15)
    assert withdraw.start_time == press.end_time and withdraw.end.time == withdraw.end_time
    # The contact is lost at Ting's t_s = 0.27700 s (the scene's comment; 1e-3 t_m, the row's
    # stated error in time).
    assert withdraw.end_time == pytest.approx(0.27700, abs=2e-4)
    assert time[-1] == withdraw.end_time


def test_an_elastic_run_names_neither_dissipation_as_its_json():
    result = mdrsim.run(mdrsim.Scene.from_file("scenes/programs/jkr_cycle_reversible.toml"))
    total, _ = json_work(result)
    assert "dissipated_at_front" not in total and "dissipated_by_bulk" not in total
    assert result.work.dissipated_at_front is None and result.work.dissipated_by_bulk is None
    assert all(s.work.dissipated_at_front is None and s.work.dissipated_by_bulk is None
               for s in result.stages)
    assert mdrsim.Work(0.0, 0.0).dissipated_by_bulk is None


def test_time_keys_set_from_python_values():
    scene = mdrsim.Scene.from_dict(RATE_LAW_DICT)
    # The law as a dict, the speed as a float: beta = 100 from beta = 1.
    fast = scene.with_values({"detachment.front_speed_law": {"speed": 1.0e-6, "exponent": 1.0},
                              "loading.stage.2.speed": 1.7099759466766972e-06})
    # docs/rate_law.md's table, n = 1, beta = 100: -8.1499919 F0 (8 digits).
    assert mdrsim.run(fast).peak.dimensionless["normal_force"] == pytest.approx(-8.1499919,
                                                                               abs=1e-7)
    # A retraction given a duration instead of its speed: the same clock.
    relaxing = mdrsim.Scene.from_dict(LEE_RADOK_DICT)
    slower = relaxing.with_values({"material.relaxation": [{"modulus": 9.0e6, "time": 1.0}]})
    two = relaxing.with_values({"material.relaxation": [{"modulus": 4.5e6, "time": 0.1},
                                                        {"modulus": 4.5e6, "time": 0.1}]})
    # Two equal arms are one arm of their summed modulus (rounding of the sums).
    assert mdrsim.run(two).work.normal == pytest.approx(mdrsim.run(relaxing).work.normal,
                                                        rel=1e-12)
    # A slower arm relaxes less during the press: more work stored, less dissipated.
    assert mdrsim.run(slower).stages[0].work.normal > mdrsim.run(relaxing).stages[0].work.normal
    held = relaxing.with_values({"loading.stage.1.duration": 0.2})
    held = held.to_dict()
    assert held["loading"]["stage"][0]["duration"] == 0.2 and "speed" not in held["loading"][
        "stage"][0]


@pytest.mark.parametrize("values, message", [
    ({"detachment.front_speed_law": {"speed": 1.0e-6, "exponent": 2.0}},
     "--set: detachment.front_speed_law.exponent = 2 is outside (0, 1]"),
    ({"loading.stage.2.speed": -1.0}, "--set: loading.stage.2.speed = -1 is outside (0, inf)"),
])
def test_bad_time_keys_raise_scene_error(values, message):
    with pytest.raises(mdrsim.SceneError) as error:
        mdrsim.Scene.from_dict(RATE_LAW_DICT).with_values(values)
    assert str(error.value) == message


def test_a_relaxation_without_a_clock_raises_scene_error():
    with pytest.raises(mdrsim.SceneError) as error:
        mdrsim.Scene.from_dict(LEE_RADOK_DICT).with_values(
            {"material.relaxation": [{"modulus": 9.0e6, "time": 0.0}]})
    assert str(error.value) == "--set: material.relaxation.1.time = 0 is outside (0, inf)"
    with pytest.raises(mdrsim.SceneError) as error:
        mdrsim.Scene.from_file("scenes/fig2_fixed_load.toml").with_values(
            {"material.relaxation": [{"modulus": 9.0e6, "time": 0.1}]})
    assert str(error.value) == (
        "--set: material.relaxation: needs a loading program whose stages all have a duration "
        "or speed; the shorthand has no clock (docs/viscoelastic.md \"What it refuses\")")
    untimed = copy.deepcopy(LEE_RADOK_DICT)
    del untimed["loading"]["stage"][1]["speed"]
    with pytest.raises(mdrsim.SceneError) as error:
        mdrsim.Scene.from_dict(untimed)
    assert str(error.value).startswith("<dict>:") and str(error.value).endswith(
        "loading.stage.2: has neither duration nor speed, which loading.stage.1 gives: a timed "
        "program gives every stage one")


def test_a_rate_sweep_gives_the_command_csv_and_its_dissipation(cli):
    speeds = "1e-9:1e-6:4:log"
    command = subprocess.run([cli, "sweep", RATE_LAW, "--vary", f"loading.stage.2.speed={speeds}",
                              "--csv", "-", "--log-level", "off"],
                             check=True, capture_output=True, text=True).stdout
    swept = mdrsim.sweep(mdrsim.Scene.from_file(RATE_LAW),
                         {"loading.stage.2.speed": speeds})
    assert swept.to_csv() == command
    assert [row["loading.stage.2.speed"] for row in swept.rows] == [1e-9, 1e-8, 1e-7, 1e-6]
    # Each row is the run's: its peak tension and what the front dissipated.
    for row in swept.rows:
        run = mdrsim.run(mdrsim.Scene.from_file(RATE_LAW).set("loading.stage.2.speed",
                                                              row["loading.stage.2.speed"]))
        assert row["peak_normal_force"] == run.peak.normal_force
        assert row["dissipated_at_front"] == run.work.dissipated_at_front
    # Faster retraction: a deeper peak and more dissipated at the front.
    peaks = [row["peak_normal_force"] for row in swept.rows]
    fronts = [row["dissipated_at_front"] for row in swept.rows]
    assert peaks == sorted(peaks, reverse=True) and fronts == sorted(fronts)
    assert "dissipated_by_bulk" not in swept.columns
    assert {row["status"] for row in swept.rows} == {"instability"}
