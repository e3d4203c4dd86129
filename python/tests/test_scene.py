"""Scenes from a file, TOML text and a dict; with_values; every kind of bad input."""

import copy
import subprocess

import pytest

import mdrsim

FIG2 = "scenes/fig2_fixed_load.toml"
FIG2_DICT = {
    "title": "Fig. 2: JKR pull-off, fixed-load",
    "material": {"youngs_modulus": 1.0e6, "poisson_ratio": 0.0, "work_of_adhesion": 0.05},
    "profile": {"type": "parabolic", "radius": 0.01},
    "loading": {"preload": {"contact_radius": 5.209397078678047e-4},
                "normal": {"control": "fixed-load"}},
    "detachment": {"criterion": "mode-mixed"},
    "discretization": {"springs": 10000, "extrapolation": "richardson"},
    "solver": {"method": "event"},
}
CYCLE_DICT = {
    "material": {"effective_modulus": 1.0e6, "work_of_adhesion": 0.05,
                 "approach_work_of_adhesion": 0.05},
    "profile": {"type": "parabolic", "radius": 0.01},
    "loading": {"stage": [
        {"name": "approach", "normal": {"control": "fixed-grips", "to": 2.0e-5}},
        {"name": "retract", "normal": {"by": -2.0e-5}, "until": "separation"},
    ]},
    "discretization": {"springs": 2000},
}


def critical_force(scene):
    return mdrsim.run(scene, trajectory=False).critical.normal_force


def test_file_text_and_dict_give_the_same_scene():
    from_file = mdrsim.Scene.from_file(FIG2)
    with open(FIG2) as f:
        from_text = mdrsim.Scene.from_toml(f.read(), name="fig2.toml")
    from_dict = mdrsim.Scene.from_dict(FIG2_DICT)
    assert from_file.source == FIG2
    assert from_text.source == "fig2.toml"
    assert from_dict.source == "<dict>"
    forces = {critical_force(s) for s in (from_file, from_text, from_dict)}
    assert len(forces) == 1
    assert from_file.title == "Fig. 2: JKR pull-off, fixed-load"
    assert from_file.springs == 10000
    assert (from_file.profile, from_file.criterion) == ("parabolic", "mode-mixed")
    assert from_file.control == ("fixed-load", "fixed-grips")
    assert from_file.material.effective_modulus == 1.0e6


def test_a_dict_with_an_array_of_tables_is_a_program():
    scene = mdrsim.Scene.from_dict(CYCLE_DICT)
    result = mdrsim.run(scene)
    assert [s.name for s in result.stages] == ["approach", "retract"]
    assert result.status == "instability"


def test_a_timed_program_from_a_dict_has_time_in_its_states_and_trajectory():
    # Press at 4 um/s for 5 s, hold 3 s, retract 10 um per unit of the stage parameter at
    # 2 um/s (5 s per unit): docs/programs.md "Time".
    table = copy.deepcopy(CYCLE_DICT)
    table["loading"]["stage"] = [
        {"name": "approach", "normal": {"control": "fixed-grips", "to": 2.0e-5}, "speed": 4.0e-6},
        {"name": "hold", "duration": 3.0},
        {"name": "retract", "normal": {"by": -1.0e-5}, "until": "separation", "speed": 2.0e-6},
    ]
    result = mdrsim.run(mdrsim.Scene.from_dict(table))
    approach, hold, retract = result.stages
    # 2e-5 / 4e-6 is 5 to one rounding; the hold adds its 3 s exactly.
    assert approach.start_time == 0.0 and approach.end_time == pytest.approx(5.0, rel=1e-15)
    assert hold.start_time == approach.end_time and hold.end_time == approach.end_time + 3.0
    assert hold.end.time == hold.end_time
    # Fixed grips: the retraction's parameter is (d - 2e-5) / -1e-5; 5 s per unit (1e-12:
    # a few roundings of the affine clock).
    c = result.critical
    assert c.time == pytest.approx(hold.end_time + 5.0 * (2.0e-5 - c.indentation) / 1.0e-5,
                                   rel=1e-12)
    jump = result.jumps[-1]
    assert jump.critical.time == jump.after.time == c.time
    time = result.trajectory["time"]
    assert time[0] >= 0.0 and time[-1] == pytest.approx(retract.end_time, rel=1e-12)
    assert all(b >= a for a, b in zip(time, time[1:]))
    assert result.to_dict()["critical"]["time"] == c.time
    # Untimed, the same path has no time anywhere and the same numbers.
    plain = mdrsim.run(mdrsim.Scene.from_dict(CYCLE_DICT))
    assert plain.critical.time is None and plain.stages[0].start_time is None
    assert "time" not in plain.trajectory


def test_with_values_is_a_new_scene_checked_like_set():
    scene = mdrsim.Scene.from_file(FIG2)
    fewer = scene.with_values({"discretization.springs": 2000, "loading.normal.control": "fixed-grips"})
    assert (scene.springs, fewer.springs) == (10000, 2000)
    assert fewer.control[0] == "fixed-grips"
    assert fewer.overrides == (("discretization.springs", "2000"),
                               ("loading.normal.control", '"fixed-grips"'))
    # JKR under fixed grips jumps at -5/9 F0 (paper eq. 33), under fixed load at -F0.
    f0 = 1.5 * 3.141592653589793 * 0.01 * 0.05
    assert critical_force(fewer) / f0 == pytest.approx(-5 / 9, abs=2e-3)
    assert critical_force(scene) / f0 == pytest.approx(-1.0, abs=2e-3)
    program = mdrsim.Scene.from_dict(CYCLE_DICT).with_values({"loading.stage.2.normal.by": -3e-5})
    assert mdrsim.run(program).status == "instability"


def test_numpy_and_list_values():
    np = pytest.importorskip("numpy")
    scene = mdrsim.Scene.from_file(FIG2).with_values({"discretization.springs": np.int64(500),
                                                      "profile.radius": np.float64(0.02)})
    assert scene.springs == 500
    table = {**FIG2_DICT, "profile": {"type": "tabulated", "r": np.linspace(0, 1e-3, 8),
                                      "f": [r * r / 0.02 for r in np.linspace(0, 1e-3, 8)]}}
    assert mdrsim.Scene.from_dict(table).profile == "tabulated"


# Each kind of bad input, with the exact one-line message of `mdrsim run` (exit code 2).
BAD = [
    pytest.param(FIG2, {"material.poisson_ratio": 0.7},
                 "--set: material.poisson_ratio = 0.7 is outside (-1, 0.5]", id="bad-value"),
    pytest.param(FIG2, {"material.poisson": 0.3},
                 "--set: material.poisson: unknown key; did you mean 'poisson_ratio'? "
                 "(known: adhesive_stress, approach_work_of_adhesion, "
                 "effective_modulus, effective_shear_modulus, grading, maugis_parameter, poisson_ratio, "
                 "relaxation, work_of_adhesion, youngs_modulus)", id="bad-key"),
    pytest.param(FIG2, {"loading.stage.2.normal.by": 1e-6},
                 "--set: loading.stage.2.normal.by: the scene has no [[loading.stage]]",
                 id="bad-override"),
    pytest.param(FIG2, {"discretization.springs": 1.5},
                 "--set: discretization.springs = 1.5 is not a whole number", id="not-whole"),
    pytest.param("scenes/no_such_scene.toml", {},
                 "scenes/no_such_scene.toml: cannot read the scene file (no such file or directory)",
                 id="bad-file"),
]


def load(path, values):
    return mdrsim.Scene.from_file(path).with_values(values)


@pytest.mark.parametrize("path,values,message", BAD)
def test_bad_input_raises_scene_error(path, values, message):
    with pytest.raises(mdrsim.SceneError) as caught:
        load(path, values)
    assert isinstance(caught.value, ValueError)
    assert str(caught.value) == message


@pytest.mark.parametrize("path,values,message", BAD)
def test_the_message_is_the_command_lines(path, values, message, cli):
    args = [cli, "run", path, "--log-level", "off"]
    for key, value in values.items():
        args += ["--set", f"{key}={value}"]
    done = subprocess.run(args, capture_output=True, text=True)
    assert (done.returncode, done.stderr) == (2, message + "\n")


def test_bad_key_in_a_file_names_its_line():
    text = open(FIG2).read().replace("poisson_ratio", "poisson_rate")
    with pytest.raises(mdrsim.SceneError) as caught:
        mdrsim.Scene.from_toml(text, name="typo.toml")
    assert str(caught.value) == (
        "typo.toml:8:1: material.poisson_rate: unknown key; did you mean 'poisson_ratio'? "
        "(known: adhesive_stress, approach_work_of_adhesion, "
        "effective_modulus, effective_shear_modulus, grading, maugis_parameter, poisson_ratio, "
        "relaxation, work_of_adhesion, youngs_modulus)")


def test_malformed_toml():
    with pytest.raises(mdrsim.SceneError, match=r"^bad\.toml:1:\d+: malformed TOML"):
        mdrsim.Scene.from_toml("[material\n", name="bad.toml")


def test_bad_dict_values():
    with pytest.raises(mdrsim.SceneError) as caught:
        mdrsim.Scene.from_dict({**FIG2_DICT, "title": None})
    assert str(caught.value) == ("<dict>: title: NoneType None is not a scene value "
                                 "(expected a number, string, boolean, list or table)")
    with pytest.raises(mdrsim.SceneError, match=r"^--set: solver\.step: object"):
        mdrsim.Scene.from_file(FIG2).with_values({"solver.step": object()})
    with pytest.raises(mdrsim.SceneError, match=r"^<dict>:\d+:\d+: material\.youngs_modulus"):
        mdrsim.Scene.from_dict({**FIG2_DICT, "material": {**FIG2_DICT["material"],
                                                          "youngs_modulus": -1.0}})


def test_strings_are_quoted_so_a_string_is_never_read_as_a_number():
    with pytest.raises(mdrsim.SceneError) as caught:
        mdrsim.Scene.from_file(FIG2).with_values({"discretization.springs": "1000"})
    assert str(caught.value) == ('--set: discretization.springs: expected a whole number, '
                                 'got string "1000"')


def test_scene_is_made_by_its_constructors_only():
    with pytest.raises(TypeError):
        mdrsim.Scene()
    with pytest.raises(TypeError):
        mdrsim.run(42)
