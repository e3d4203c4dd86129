"""Result.curve(stage=...): a stage's rows from the state it starts in, so that a retract that
starts pinned keeps its pinned unloading; checked by fitting JKR's closed form to it."""

import numpy as np
import pytest

import mdrsim

R = 0.01          # [m] parabolic tip
E_STAR = 1.0e6    # [Pa] E* (nu = 0)
W = 0.05          # [J/m^2] the work of adhesion to recover
D0 = 2.2615e-6    # [m] JKR's depth scale of the scene below


def cycle_scene():
    """scenes/programs/jkr_cycle_glue_on_touch.toml: a Hertz approach (glue on touch) to 3 d0
    under fixed grips, then a retract until separation."""
    return mdrsim.Scene.from_file("scenes/programs/jkr_cycle_glue_on_touch.toml")


def jkr_retract_force(d, e_star, w, d_max):
    """JKR's closed form of the fixed-grips retract from a contact glued on touch at d_max (the
    MDR of the paraboloid): pinned at a_max = sqrt(R d_max), F = 2 E* a (d - a^2 / (3 R)),
    until d_max - d reaches s(a_max) = sqrt(2 pi a_max w / E*); then on the branch
    d = a^2 / R - s(a) at the same F(a, d), a between the fold a* and a_max."""
    s = lambda a: np.sqrt(2 * np.pi * a * w / e_star)  # noqa: E731
    a_max = np.sqrt(R * d_max)
    a_fold = (R / 4 * np.sqrt(2 * np.pi * w / e_star)) ** (2 / 3)
    low, high = np.full_like(d, a_fold), np.full_like(d, a_max)
    for _ in range(80):  # bisection: a^2/R - s(a) rises with a above the fold
        mid = 0.5 * (low + high)
        above = mid**2 / R - s(mid) > d
        high, low = np.where(above, mid, high), np.where(above, low, mid)
    a = np.where(d >= d_max - s(a_max), a_max, 0.5 * (low + high))
    return 2 * e_star * a * (d - a**2 / (3 * R))


def fit_jkr(d, force, d_max, start=(2.0e6, 0.02)):
    """(E*, w) minimising the squared misfit of the closed form: Levenberg-Marquardt in
    (log E*, log w), forward-difference Jacobian, written here to stay apart from the engine's
    fit."""
    scale = np.abs(force).max()
    residuals = lambda p: (jkr_retract_force(d, *np.exp(p), d_max) - force) / scale  # noqa: E731
    p = np.log(np.asarray(start, float))
    r = residuals(p)
    damping = 1e-3
    for _ in range(300):
        jacobian = np.column_stack([(residuals(p + h) - r) / 1e-7 for h in np.eye(2) * 1e-7])
        normal = jacobian.T @ jacobian
        step = np.linalg.lstsq(normal + damping * np.diag(np.diag(normal)), -jacobian.T @ r,
                               rcond=None)[0]
        trial = residuals(p + step)
        if trial @ trial < r @ r:
            p, r, damping = p + step, trial, damping / 3
            if np.abs(step).max() < 1e-10:
                break
        else:
            damping *= 4
    return np.exp(p)


def as_measured(curve, d_max):
    """The retract sampled as an instrument would: 400 equal steps of the piezo from where the
    retract starts (d_max, the approach's end) to the last equilibrium before the jump off,
    the force between rows interpolated (affine between two rows: no spring changes there),
    held at the end rows beyond them as np.interp does."""
    keep = ~np.asarray(curve["in_cascade"], bool)
    d, f = curve["indentation"][keep], curve["normal_force"][keep]
    order = np.argsort(d, kind="stable")
    grid = np.linspace(d.min(), d_max, 400)
    return grid, np.interp(grid, d[order], f[order])


def test_a_stages_curve_starts_at_the_state_the_previous_stage_ended_in():
    result = mdrsim.run(cycle_scene())
    t = result.trajectory
    retract = result.curve(stage="retract")
    own = [i for i, s in enumerate(t["stage"]) if s == "retract"]
    # The first row is the approach's last (its stage-end), unchanged; then the retract's own.
    assert retract["stage"][0] == "approach" and retract["event"][0] == "stage-end"
    assert retract["stage"][1:] == ["retract"] * len(own)
    assert retract["indentation"][0] == result.stages[0].end.indentation
    assert retract["normal_force"][0] == result.stages[0].end.normal_force
    np.testing.assert_array_equal(retract["normal_force"][1:], t["normal_force"][own])
    assert set(retract) == set(t)
    # The first stage starts untouched, which has no row: its curve is its own rows.
    approach = result.curve(stage="approach")
    assert approach["stage"] == ["approach"] * len(approach["event"])
    assert len(result.curve()["event"]) == len(t["event"])
    with pytest.raises(KeyError, match="stage 'unload': no rows .*approach, retract"):
        result.curve(stage="unload")
    with pytest.raises(ValueError, match="no trajectory"):
        mdrsim.run(cycle_scene(), trajectory=False).curve(stage="retract")


def test_jkr_closed_form_fitted_to_the_retract_curve_gives_back_the_work_of_adhesion():
    result = mdrsim.run(cycle_scene())
    d_max = result.stages[0].end.indentation
    assert d_max == pytest.approx(3 * D0, rel=1e-4)
    curve = result.curve(stage="retract")
    d, force = as_measured(curve, d_max)
    e_star, w = fit_jkr(d, force, d_max)
    # 1 %: the row's 4000 springs put each let-go within one spring spacing (a_max / 4000)
    # of the branch; the closed form is exact otherwise (observed: 5e-5 in both).
    assert w == pytest.approx(W, rel=0.01)
    assert e_star == pytest.approx(E_STAR, rel=0.01)
    # The trap: the stage's own rows begin at the first let-go, d = -d0; the pinned unloading
    # from 3 d0 is missing, and the curve interpolated over them holds the force flat there,
    # far from JKR's path (a fit of (E*, w) to it gave E* = 0.40 MPa, w = 0.039). From its
    # starting state the curve is JKR's to 0.1 % of the largest force.
    own = {key: value[1:] for key, value in curve.items()}
    assert own["event"][0] == "detached"
    _, held = as_measured(own, d_max)
    truth = jkr_retract_force(d, E_STAR, W, d_max)
    assert np.abs(force - truth).max() < 1e-3 * np.abs(truth).max()
    assert np.abs(held - truth).max() > 0.5 * np.abs(truth).max()
