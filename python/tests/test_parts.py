"""Criteria and profiles written in Python: registered by one call, used from a scene."""

import math
import threading

import pytest

import mdrsim

# Fig. 3a under fixed load with nu = 0.3 (E* != G*) and u = d0: the tangential term matters.
SCENE = mdrsim.Scene.from_file("scenes/fig3a_fixed_load.toml").with_values(
    {"material.poisson_ratio": 0.3, "discretization.springs": 2000})


def mode_mixed_margin(elongation, tangential_displacement, contact_radius, material):
    """Paper eq. 20, as detachment/mode_mixed_criterion.cpp writes it."""
    return (2.0 * math.pi * contact_radius * material.work_of_adhesion
            - material.effective_modulus * elongation * elongation
            - material.effective_shear_modulus * tangential_displacement * tangential_displacement)


def mode_mixed_elongation(contact_radius, tangential_displacement, material):
    """Paper eq. 21, with the C++ criterion's order of operations."""
    squared = (2.0 * math.pi * (material.work_of_adhesion / material.effective_modulus)
               * contact_radius
               - material.effective_shear_modulus / material.effective_modulus
               * tangential_displacement * tangential_displacement)
    return math.sqrt(squared) if squared > 0.0 else 0.0


mdrsim.register_criterion("py-mode-mixed", mode_mixed_margin,
                          critical_elongation=mode_mixed_elongation,
                          summary="paper eq. 20 in Python")
mdrsim.register_criterion("py-mode-mixed-margin-only", mode_mixed_margin)
mdrsim.register_criterion(
    "py-scaled-hess",
    lambda e, ux, a, m, factor: factor * math.sqrt(2 * math.pi * a * m.work_of_adhesion
                                                   / m.effective_modulus) - e,
    parameters={"factor": mdrsim.Parameter(help="[1]", above=0.0, at_most=10.0)})
mdrsim.register_profile("py-parabola", lambda r, radius: r * r / (2 * radius),
                        lambda x, radius: x * x / radius,
                        parameters={"radius": mdrsim.Parameter(help="R [m]", above=0.0)},
                        tip_radius="radius")
mdrsim.register_profile("py-parabola-shape-only", lambda r, radius: r * r / (2 * radius),
                        parameters=["radius"], tip_radius="radius")


def critical(scene):
    return mdrsim.run(scene, trajectory=False).critical


def with_criterion(name, **values):
    return SCENE.with_values({"detachment.criterion": name, **values})


def test_python_mode_mixed_matches_the_builtin():
    builtin = critical(SCENE)
    closed_form = critical(with_criterion("py-mode-mixed"))
    assert closed_form.springs_in_contact == builtin.springs_in_contact
    assert closed_form.normal_force == pytest.approx(builtin.normal_force, rel=1e-12, abs=0)
    assert closed_form.indentation == pytest.approx(builtin.indentation, rel=1e-12, abs=0)


def test_python_margin_alone_is_root_found():
    builtin = critical(SCENE)
    result = mdrsim.run(with_criterion("py-mode-mixed-margin-only"), trajectory=False)
    assert result.counts["root_iterations"] > 0
    assert result.critical.springs_in_contact == builtin.springs_in_contact
    assert result.critical.normal_force == pytest.approx(builtin.normal_force, rel=1e-12, abs=0)


def test_parameters_are_read_and_checked_from_the_scene():
    # factor 1 is the normal-only rule, as in tests/engine/scene/user_parts_test.cpp.
    normal_only = critical(with_criterion("normal-only"))
    assert critical(with_criterion("py-scaled-hess", **{"detachment.factor": 1.0})).normal_force \
        == pytest.approx(normal_only.normal_force, rel=1e-12)
    stronger = critical(with_criterion("py-scaled-hess", **{"detachment.factor": 1.5}))
    assert stronger.normal_force < normal_only.normal_force
    with pytest.raises(mdrsim.SceneError) as caught:
        with_criterion("py-scaled-hess", **{"detachment.factor": 0.0})
    assert str(caught.value) == "--set: detachment.factor = 0 is outside (0, 10]"
    with pytest.raises(mdrsim.SceneError, match=r"detachment\.factor: missing"):
        with_criterion("py-scaled-hess")
    with pytest.raises(mdrsim.SceneError, match=r"detachment\.factor.*py-scaled-hess"):
        with_criterion("py-mode-mixed", **{"detachment.factor": 1.0})


def test_python_parabola_matches_the_builtin():
    builtin = critical(SCENE)
    ours = mdrsim.run(SCENE.with_values({"profile.type": "py-parabola"}), trajectory=False)
    assert ours.critical.springs_in_contact == builtin.springs_in_contact
    assert ours.critical.normal_force == pytest.approx(builtin.normal_force, rel=1e-12, abs=0)
    assert ours.dimensionless["normal_force"] == pytest.approx(
        builtin.dimensionless["normal_force"], rel=1e-12)


def test_python_profile_without_image_uses_eq_4():
    builtin = critical(SCENE.with_values({"discretization.springs": 400}))
    ours = critical(SCENE.with_values({"profile.type": "py-parabola-shape-only",
                                       "discretization.springs": 400}))
    assert ours.springs_in_contact == builtin.springs_in_contact
    # g from f by tanh-sinh over a finite-difference slope: 1.6e-13 relative here.
    assert ours.normal_force == pytest.approx(builtin.normal_force, rel=1e-10)


def test_known_parts_and_names():
    parts = mdrsim.parts()
    assert parts["criteria"]["py-mode-mixed"] == "paper eq. 20 in Python"
    assert "mode-mixed" in parts["criteria"] and "py-parabola" in parts["profiles"]
    assert "fixed-load" in parts["controllers"]
    with pytest.raises(ValueError, match="criterion 'mode-mixed' is built in"):
        mdrsim.register_criterion("mode-mixed", mode_mixed_margin)
    with pytest.raises(TypeError, match="margin must be callable"):
        mdrsim.register_criterion("py-broken", 3.0)
    with pytest.raises(mdrsim.SceneError, match="unknown 'py-nothing'"):
        with_criterion("py-nothing")


def test_registering_again_replaces_the_part():
    mdrsim.register_criterion("py-replaced", lambda e, ux, a, m: -1.0)
    scene = with_criterion("py-replaced")
    mdrsim.register_criterion("py-replaced", mode_mixed_margin)
    assert critical(with_criterion("py-replaced")).normal_force == pytest.approx(
        critical(SCENE).normal_force, rel=1e-12)
    assert mdrsim.run(scene).critical != critical(SCENE)  # built with the old part


def test_an_exception_in_python_code_reaches_the_caller():
    def failing(e, ux, a, m):
        raise ZeroDivisionError("from the margin")

    mdrsim.register_criterion("py-failing", failing)
    with pytest.raises(ZeroDivisionError, match="from the margin"):
        mdrsim.run(with_criterion("py-failing"))
    mdrsim.register_criterion("py-nan", lambda e, ux, a, m: float("nan"))
    with pytest.raises(ValueError, match="'py-nan': margin returned nan, not a finite number"):
        mdrsim.run(with_criterion("py-nan"))
    mdrsim.register_criterion("py-none", lambda e, ux, a, m: None)
    with pytest.raises(TypeError):
        mdrsim.run(with_criterion("py-none"))
    assert critical(SCENE) is not None  # and the engine is fine afterwards


def test_python_parts_from_two_threads():
    scene = with_criterion("py-mode-mixed-margin-only")
    expected = critical(scene)
    results = [None, None]

    def work(i):
        results[i] = critical(scene)

    threads = [threading.Thread(target=work, args=(i,)) for i in range(2)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert results == [expected, expected]
