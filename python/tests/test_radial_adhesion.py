"""A work of adhesion that varies with the radius (docs/scene.md "Adhesion that varies with
radius") from Python: tables as NumPy arrays and sinusoids as dicts through with_values and
from_dict, the engine's checks on them, and Material.work_of_adhesion_at in a criterion
written in Python."""

import math

import numpy as np
import pytest

import mdrsim

# Fig. 2 under fixed load, one row of 1000 springs (0.3 ms): glued at 2 a0 = 5.2e-4 m, it
# pulls off at a contact radius near a0 = 2.6e-4 m, inside the table below.
FIG2 = mdrsim.Scene.from_file("scenes/fig2_fixed_load.toml").with_values(
    {"discretization.springs": 1000, "discretization.extrapolation": "none"})
# The crack-front test case: a loading program (approach, retract), 2000 springs, ~1 ms.
SINUSOID = "scenes/programs/crack_front_sinusoid.toml"
MEAN = 0.3183098861837907  # 1/pi, the file's mean

R = np.array([0.0, 1.5e-4, 3e-4, 3e-4, 6e-4])  # a step at 3e-4 m
VALUE = np.array([0.05, 0.08, 0.06, 0.07, 0.05])
# The same table as the scene file would write it.
FIG2_WITH_TABLE = """\
title = "Fig. 2 with a table of dgamma(r)"

[material]
youngs_modulus = 1.0e6
poisson_ratio = 0.0
work_of_adhesion = { r = [0.0, 1.5e-4, 3e-4, 3e-4, 6e-4], value = [0.05, 0.08, 0.06, 0.07, 0.05] }

[profile]
type = "parabolic"
radius = 0.01

[loading]
preload = { contact_radius = 5.209397078678047e-4 }
normal = { control = "fixed-load" }

[detachment]
criterion = "mode-mixed"

[discretization]
springs = 1000
"""


def run(scene):
    return mdrsim.run(scene, trajectory=False)


def same_answer(a, b):
    """Bit for bit: the critical state (forces, radius, springs, dimensionless), the peak,
    every jump and the work."""
    assert a.status == b.status
    assert a.critical == b.critical
    assert a.peak == b.peak
    assert a.jumps == b.jumps
    assert a.work == b.work


def table(r=R, value=VALUE):
    return {"material.work_of_adhesion": {"r": r, "value": value}}


def test_numpy_table_is_the_same_table_written_in_toml():
    from_numpy = FIG2.with_values(table())
    assert from_numpy.overrides[-1] == (
        "material.work_of_adhesion",
        "{ r = [0.0, 0.00015, 0.0003, 0.0003, 0.0006], value = [0.05, 0.08, 0.06, 0.07, 0.05] }")
    written = mdrsim.Scene.from_toml(FIG2_WITH_TABLE)
    ours, theirs = run(from_numpy), run(written)
    same_answer(ours, theirs)
    assert ours.critical.normal_force == theirs.critical.normal_force  # said twice: the point
    # The table matters: the uniform 0.05 pulls off at another force.
    assert ours.critical.normal_force != run(FIG2).critical.normal_force
    # A dict of arrays in from_dict, and lists of NumPy scalars, are the same table.
    values = written.to_dict()
    values["material"]["work_of_adhesion"] = {"r": R, "value": list(VALUE)}
    same_answer(run(mdrsim.Scene.from_dict(values)), theirs)
    assert from_numpy.to_dict()["material"]["work_of_adhesion"] == {"r": R.tolist(),
                                                                    "value": VALUE.tolist()}
    # What the engine holds: the table at its points, an array of radii in, an array out
    # (a step's radius takes the outer value).
    material = from_numpy.material
    at = material.work_of_adhesion_at(np.array([0.0, 1.5e-4, 3e-4, 6e-4, 1.0]))
    assert isinstance(at, np.ndarray) and at.tolist() == [0.05, 0.08, 0.07, 0.05, 0.05]
    assert material.work_of_adhesion_at(2.25e-4) == pytest.approx(0.07, rel=1e-15)
    assert material.work_of_adhesion == 0.05  # the scale value, the table's at r = 0
    assert "work_of_adhesion_by_radius='a table of 5 points'" in repr(material)


def test_float32_and_0d_arrays_give_their_values_exactly():
    r32, v32 = R.astype(np.float32), VALUE.astype(np.float32)
    scene = FIG2.with_values(table(r32, v32))
    # Each float32 as the double it is (1.5e-4 in float32 is 1.500000071246177e-4).
    as_doubles = FIG2.with_values(table([float(x) for x in r32], [float(x) for x in v32]))
    assert scene.overrides[-1] == as_doubles.overrides[-1]
    assert scene.overrides[-1][1].startswith("{ r = [0.0, 0.0001500000071246177, ")
    same_answer(run(scene), run(as_doubles))
    assert scene.material.work_of_adhesion_at(float(r32[1])) == float(v32[1])
    # 0-d arrays and NumPy scalars are numbers; 1-d arrays of integers are integers.
    number = FIG2.with_values({"material.work_of_adhesion": np.array(0.05)})
    assert number.overrides[-1] == ("material.work_of_adhesion", "0.05")
    sinusoid = FIG2.with_values({"material.work_of_adhesion": {
        "mean": np.array(0.05), "amplitude": np.float32(0.25), "wavelength": np.float64(1e-4)}})
    assert sinusoid.overrides[-1][1] == "{ mean = 0.05, amplitude = 0.25, wavelength = 0.0001 }"
    ints = FIG2.with_values(table(np.array([0, 1], dtype=np.int32), np.array([0, 0], np.uint8)))
    assert ints.overrides[-1][1] == "{ r = [0, 1], value = [0, 0] }"


def test_a_constant_table_is_the_number_bit_for_bit():
    number = run(FIG2)
    for constant in (table(R, np.full(R.size, 0.05)), table(np.array([0.0]), np.array([0.05])),
                     {"material.work_of_adhesion": {"mean": 0.05, "amplitude": 0.0,
                                                    "wavelength": 1e-4}}):
        scene = FIG2.with_values(constant)
        assert scene.material.work_of_adhesion_at(2e-4) == 0.05
        same_answer(run(scene), number)
    # On the program both ways, the approach's table too: the uniform loop of 1/pi.
    uniform = mdrsim.Scene.from_file(SINUSOID).with_values(
        {"material.work_of_adhesion": MEAN, "material.approach_work_of_adhesion": MEAN})
    flat = np.full(3, MEAN)
    as_tables = uniform.with_values(
        {"material.work_of_adhesion": {"r": np.array([0.0, 0.5, 1.0]), "value": flat},
         "material.approach_work_of_adhesion": {"r": np.array([0.0, 0.25, 2.0]), "value": flat}})
    same_answer(run(as_tables), run(uniform))


def test_sinusoid_from_a_dict_is_the_files():
    file = mdrsim.Scene.from_file(SINUSOID)
    wave = {"mean": MEAN, "amplitude": 0.2, "wavelength": 0.1}
    from_dict = file.with_values({"material.work_of_adhesion": wave,
                                  "material.approach_work_of_adhesion": dict(wave)})
    assert from_dict.to_dict()["material"]["work_of_adhesion"] == wave
    theirs = run(file)
    same_answer(run(from_dict), theirs)
    r = np.linspace(0.0, 1.0, 101)
    assert from_dict.material.work_of_adhesion_at(r) == pytest.approx(
        MEAN * (1.0 + 0.2 * np.sin(2.0 * np.pi * r / 0.1)), rel=1e-14)
    # A smaller ripple: the pull-off moves toward the uniform loop's -5/6 (a shallower one).
    smaller = dict(wave, amplitude=0.1)
    calmer = run(file.with_values({"material.work_of_adhesion": smaller,
                                   "material.approach_work_of_adhesion": smaller}))
    assert theirs.critical.normal_force < calmer.critical.normal_force < -5.0 / 6.0 + 1e-3


@pytest.mark.parametrize("values, message", [
    # Refused here: no scene key takes an array of arrays.
    (table(R.reshape(1, -1)), r"--set: material.work_of_adhesion.r: a 2-D array of shape "
     r"\(1, 5\) is not a scene value \(expected a 1-D array\)"),
    (table(value=VALUE.reshape(5, 1, 1)), r"--set: material.work_of_adhesion.value: a 3-D array "
     r"of shape \(5, 1, 1\) is not a scene value \(expected a 1-D array\)"),
    # Refused by the engine, by index, as any number that is not finite.
    (table(value=np.array([0.05, np.nan, 0.06, 0.07, 0.05])),
     r"--set: material.work_of_adhesion.value\[1\] = nan is not a finite number"),
    (table(r=np.array([0.0, 1.5e-4, 3e-4, 3e-4, np.inf], dtype=np.float32)),
     r"--set: material.work_of_adhesion.r\[4\] = inf is not a finite number"),
    ({"material.work_of_adhesion": np.array(-np.inf)},
     r"--set: material.work_of_adhesion = -inf is not a finite number"),
    ({"material.work_of_adhesion": {"mean": 0.05, "amplitude": np.nan, "wavelength": 1e-4}},
     r"--set: material.work_of_adhesion.amplitude = nan is not a finite number"),
    # The engine's checks of a table and of a sinusoid.
    (table(r=np.array([0.0, 3e-4, 1.5e-4, 4e-4, 6e-4])),
     r"--set: material.work_of_adhesion.r: r\[2\] = 0.00015 is below r\[1\] = 0.0003: expected "
     r"radii in increasing order"),
    (table(value=np.array([0.05, -0.08, 0.06, 0.07, 0.05])),
     r"--set: material.work_of_adhesion.value: value\[1\] = -0.08 at r = 0.00015 is not a "
     r"finite work of adhesion >= 0"),
    (table(value=VALUE[:3]),
     r"--set: material.work_of_adhesion.value: has 3 values for 5 radii: expected as many of "
     r"each"),
    ({"material.work_of_adhesion": {"mean": 0.05, "amplitude": 1.5, "wavelength": 1e-4}},
     r"--set: material.work_of_adhesion.amplitude = 1.5 is outside \[0, 1\]"),
    # dgamma_a above dgamma: named at the first radius where it is, a point of a table ...
    ({**table(), "material.approach_work_of_adhesion": {"r": R,
                                                         "value": VALUE + [0, 0.01, 0, 0, 0]}},
     r"--set: material.approach_work_of_adhesion: dgamma_a = 0.09 is above work_of_adhesion's "
     r"dgamma = 0.08 at r = 0.00015 m \(0 <= dgamma_a <= dgamma at every radius\)"),
    # ... or just inside a step, where dgamma takes its inner value.
    ({**table(), "material.approach_work_of_adhesion": {"r": R,
                                                         "value": VALUE + [0, 0, 0.02, 0, 0]}},
     r"--set: material.approach_work_of_adhesion: dgamma_a = 0.08 is above work_of_adhesion's "
     r"dgamma = 0.060000000000000005 at r = 0.0002999999999999999 m \(0 <= dgamma_a <= dgamma at "
     r"every radius\)"),
])
def test_bad_tables_raise_scene_error_naming_the_key(values, message):
    with pytest.raises(mdrsim.SceneError, match=f"^{message}$") as caught:
        FIG2.with_values(values)
    assert "\n" not in str(caught.value)


def test_bad_tables_in_files_and_dicts_name_file_line_and_key():
    # Where the engine reads the table from text, the message has file:line:column.
    text = FIG2_WITH_TABLE.replace("value = [0.05, 0.08", "value = [0.05, -0.08")
    with pytest.raises(mdrsim.SceneError, match=r"^w\.toml:6:67: material\.work_of_adhesion\."
                       r"value: value\[1\] = -0\.08 at r = 0\.00015 is not a finite work of "
                       r"adhesion >= 0$"):
        mdrsim.Scene.from_toml(text, name="w.toml")
    values = mdrsim.Scene.from_toml(FIG2_WITH_TABLE).to_dict()
    values["material"]["work_of_adhesion"]["r"] = R[::-1]
    with pytest.raises(mdrsim.SceneError, match=r"^<dict>:\d+:\d+: material\.work_of_adhesion\."
                       r"r: r\[1\] = 0\.0003 is below r\[0\] = 0\.0006: expected radii in "
                       r"increasing order$"):
        mdrsim.Scene.from_dict(values)
    # A --set that breaks dgamma_a <= dgamma against the file's own approach table: the
    # message names the file's line of it.
    with pytest.raises(mdrsim.SceneError, match=r"^scenes/programs/crack_front_sinusoid\.toml:"
                       r"14:\d+: material\.approach_work_of_adhesion: dgamma_a = [0-9.]+ is "
                       r"above work_of_adhesion's dgamma = [0-9.]+ at r = [0-9.e-]+ m "):
        mdrsim.Scene.from_file(SINUSOID).set("material.work_of_adhesion.amplitude", 0.1)


def hess_limit(contact_radius, material):
    """sqrt(2 pi a dgamma(a) / E*) in the arithmetic of engine/base/hess_scale.hpp:
    2 pi (dgamma / E*), times a."""
    w = material.work_of_adhesion_at(contact_radius)
    return math.sqrt(2.0 * math.pi * (w / material.effective_modulus) * contact_radius)


mdrsim.register_criterion(
    "py-radial-normal-only",
    lambda elongation, ux, a, material: hess_limit(a, material) - elongation,
    critical_elongation=lambda a, ux, material: hess_limit(a, material),
    summary="normal-only with dgamma(a), in Python")
mdrsim.register_criterion(
    "py-radial-normal-only-margin",
    lambda elongation, ux, a, material: hess_limit(a, material) - elongation)
mdrsim.register_criterion(  # the scale value at every radius
    "py-uniform-normal-only",
    lambda elongation, ux, a, m: math.sqrt(
        2.0 * math.pi * (m.work_of_adhesion / m.effective_modulus) * a) - elongation)


@pytest.mark.parametrize("scene", [FIG2.with_values(table()), mdrsim.Scene.from_file(SINUSOID)],
                         ids=["fig2-table", "crack-front-sinusoid"])
def test_python_criterion_with_work_of_adhesion_at_is_the_builtin_normal_only(scene):
    builtin = run(scene.set("detachment.criterion", "normal-only"))
    ours = run(scene.set("detachment.criterion", "py-radial-normal-only"))
    assert ours.critical.springs_in_contact == builtin.critical.springs_in_contact
    assert ours.critical.normal_force == builtin.critical.normal_force  # its closed form
    same_answer(ours, builtin)
    # Root-found on the margin alone: to the root finder's tolerance.
    found = run(scene.set("detachment.criterion", "py-radial-normal-only-margin"))
    assert found.counts["root_iterations"] > 0
    assert found.critical.springs_in_contact == builtin.critical.springs_in_contact
    assert found.critical.normal_force == pytest.approx(builtin.critical.normal_force,
                                                        rel=1e-12, abs=0)
    # The scale value alone at every radius is another answer.
    uniform = run(scene.set("detachment.criterion", "py-uniform-normal-only"))
    assert uniform.critical.normal_force != pytest.approx(builtin.critical.normal_force,
                                                          rel=1e-6)
