"""material.grading from Python: a graded scene built from a dict runs on both routes and as a
program, against the graded parabola's closed forms (docs/graded.md), and a wrong key or value
in the table raises SceneError naming it, as the command line does."""

import math

import pytest

import mdrsim

R = 0.01       # parabola radius [m]
DGAMMA = 0.05  # work of adhesion [J/m^2]


def graded(k=0.5, **loading):
    return {
        "material": {"youngs_modulus": 1.0e6, "poisson_ratio": 0.3, "work_of_adhesion": DGAMMA,
                     "grading": {"exponent": k, "depth": 1.0e-3}},
        "profile": {"type": "parabolic", "radius": R},
        "loading": loading or {"preload": {"contact_radius": 2.0e-3},
                               "normal": {"control": "fixed-load"}},
    }


def fixed_load_pull_off(k):
    return -(3.0 + k) * math.pi * DGAMMA * R / 2.0


def fixed_grips_jump(k):
    return -(1.0 - k) * (5.0 + 3.0 * k) * math.pi * DGAMMA * R / (2.0 * (3.0 + k))


@pytest.mark.parametrize("k", [0.25, 0.75])
def test_a_graded_scene_from_a_dict_runs_on_the_continuum_route(k):
    # -(3 + k) pi dgamma R / 2 whatever nu and E0; the route's rtol 1e-10: 1e-8.
    result = mdrsim.run(mdrsim.Scene.from_dict(graded(k)), trajectory=False)
    assert result.status == "instability"
    assert result.critical.normal_force / fixed_load_pull_off(k) == pytest.approx(1.0, abs=1e-8)
    assert result.accuracy["route"] == "continuum"
    # The JKR scales do not apply to a graded half-space: none.
    assert result.scales is None


def test_a_graded_scene_takes_the_spring_row_with_method_event():
    # The row at rtol 1e-6 lies within its own estimate of the closed form.
    scene = mdrsim.Scene.from_dict({**graded(0.5), "discretization": {"rtol": 1e-6}})
    result = mdrsim.run(scene.with_method("event"), trajectory=False)
    exact = fixed_load_pull_off(0.5)
    assert result.accuracy["route"] != "continuum"
    assert abs(result.critical.normal_force - exact) <= result.accuracy["critical_error_estimate"]


def test_a_graded_program_from_a_dict_runs():
    # Press to 2.5e-4 m and retract until separation under fixed grips: the jump-out is the
    # fold of the graded branch, -(1 - k)(5 + 3k) pi dgamma R / (2 (3 + k)), to 1e-8.
    k = 0.5
    scene = mdrsim.Scene.from_dict(graded(k, stage=[
        {"name": "approach", "normal": {"control": "fixed-grips", "to": 2.5e-4}},
        {"name": "retract", "normal": {"control": "fixed-grips", "by": -1.0e-4},
         "until": "separation"}]))
    result = mdrsim.run(scene, trajectory=False)
    assert [s.name for s in result.stages] == ["approach", "retract"]
    assert result.jumps[-1].kind == "out"
    assert result.critical.normal_force / fixed_grips_jump(k) == pytest.approx(1.0, abs=1e-8)
    # The exponent changed through with_values, as on the command line.
    softer = mdrsim.run(scene.with_values({"material.grading.exponent": 0.25}), trajectory=False)
    assert softer.critical.normal_force / fixed_grips_jump(0.25) == pytest.approx(1.0, abs=1e-8)


@pytest.mark.parametrize("grading, message", [
    ({"exponent": 0.5, "dept": 1.0e-3},
     "material.grading.dept: unknown key; did you mean 'depth'? (known: depth, exponent)"),
    ({"exponent": 1.0, "depth": 1.0e-3}, "material.grading.exponent = 1 is outside [0, 1)"),
])
def test_a_wrong_grading_key_raises_scene_error_naming_it(grading, message):
    table = graded()
    table["material"]["grading"] = grading
    with pytest.raises(mdrsim.SceneError) as caught:
        mdrsim.Scene.from_dict(table)
    assert isinstance(caught.value, ValueError)
    assert str(caught.value).endswith(message)


def test_a_wrong_grading_override_raises_scene_error_naming_it():
    scene = mdrsim.Scene.from_dict(graded())
    with pytest.raises(mdrsim.SceneError) as caught:
        scene.with_values({"material.grading.dept": 1.0})
    assert str(caught.value) == ("--set: material.grading.dept: unknown key; did you mean "
                                 "'depth'? (known: depth, exponent)")
