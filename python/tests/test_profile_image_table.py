"""A Python profile without `image`: eq. 4 tabulated once per octave of x, not per event."""

import pytest

import mdrsim

CALLS = {"shape": 0}


def power_law(r, coefficient, exponent):
    CALLS["shape"] += 1
    return coefficient * r ** exponent


mdrsim.register_profile("py-power-law-shape-only", power_law,
                        parameters=["coefficient", "exponent"])
POWER = "scenes/power_law_fixed_load.toml"


def shape_calls(springs, exponent):
    """The calls of the shape to build and run the scene, on a fresh table (a new exponent
    each time: tables are shared between scenes of the same parameters)."""
    CALLS["shape"] = 0
    scene = mdrsim.Scene.from_file(POWER).with_values(
        {"profile.type": "py-power-law-shape-only", "profile.exponent": exponent,
         "discretization.springs": springs})
    result = mdrsim.run(scene, trajectory=False)
    return CALLS["shape"], result


def test_shape_calls_do_not_grow_with_the_springs():
    # At eq. 4 per call (about 1 ms and 3,000 shape calls per event here): twice the springs,
    # twice the calls (and 2.6 s for the scene's 2000 springs). Tabulated, a few more octaves
    # of x at most (log2 N octaves of 9 to 513 knots, built once).
    few, _ = shape_calls(2000, 1.5 + 1e-9)
    many, _ = shape_calls(16000, 1.5 + 2e-9)
    assert many < 1.5 * few


@pytest.mark.parametrize("exponent", [1.5, 1.25])
def test_tabulated_image_gives_the_builtin_power_laws_numbers(exponent):
    builtin = mdrsim.run(mdrsim.Scene.from_file(POWER).with_values(
        {"profile.exponent": exponent, "discretization.springs": 3000}), trajectory=False)
    _, ours = shape_calls(3000, exponent)
    c, b = ours.critical, builtin.critical
    assert c.springs_in_contact == b.springs_in_contact
    # The table's own tolerance is 1e-11 of g; eq. 4 by a finite-difference slope is good to
    # about 1e-12: both far below the row's 1/N = 3e-4. (Untabulated: 4e-12 off, 2000 springs.)
    assert c.normal_force == pytest.approx(b.normal_force, rel=1e-9)
    assert c.indentation == pytest.approx(b.indentation, rel=1e-9)
