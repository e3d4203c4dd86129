"""From adhesion to sliding friction (docs/friction.md): a sphere glued at a_g and sheared
under fixed grips, chi = mu F_z / F_x,peak below and above 1, against its closed forms."""

import math

import pytest

import mdrsim

SCENES = {"below": "scenes/programs/adhesion_to_friction_chi_below.toml",
          "above": "scenes/programs/adhesion_to_friction_chi_above.toml"}
SPRINGS = 1000

# The scenes' values: R = 1 cm, E* = G* = 1 MPa (nu = 0), dgamma = 0.05 J/m^2, glued on
# touch to d = 12 d0 under fixed grips, then u_x from 0 to 40 um with d held.
RADIUS, MODULUS, SHEAR_MODULUS, WORK = 0.01, 1.0e6, 1.0e6, 0.05
DEPTH, TRAVEL = 2.713781792333937e-5, 4.0e-5


class Transition:
    """The closed forms, derived here apart from the engine. Glued on touch to d, every spring
    within a_g = sqrt(R d) is glued with its tangential stretch zero, the edge unstretched
    normally; F_z = 4 E* a_g^3/(3R) (Hertz). Sheared by u, every glued spring carries G* u per
    length: F_x = 2 G* a_g u. The edge lets go where G* u^2 = 2 pi a_g dgamma (its elongation
    the critical one, u_z = 0), at u_c, F_x,peak = 2 G* a_g u_c = 2 sqrt(2 pi dgamma G*)
    a_g^(3/2); the springs inside have the same u and a smaller critical elongation, so the
    whole glue goes in one jump. Each spring then keeps its stretch and slips to its limit mu
    l_z = mu E* (d - x^2/R) where the stretch exceeds it: the spring at x sticks iff G* u <=
    mu l_z(x), Cattaneo-Mindlin's loading curve from 0, so F_x = L(u) = mu F_z [1 - (1 -
    u/u*)^(3/2)] from u_c on, u* = mu E* d / G*, up to mu F_z at u*. The machine's tangential
    work to U >= u*: G* a_g u_c^2 + mu F_z [(U - u_c) - (2/5) u* (1 - u_c/u*)^(5/2)]."""

    def __init__(self, mu):
        self.mu = mu
        self.a = math.sqrt(RADIUS * DEPTH)
        self.normal_force = 4 * MODULUS * self.a ** 3 / (3 * RADIUS)
        self.u_c = math.sqrt(2 * math.pi * self.a * WORK / SHEAR_MODULUS)
        self.peak = 2 * math.sqrt(2 * math.pi * WORK * SHEAR_MODULUS) * self.a ** 1.5
        self.u_star = mu * MODULUS * DEPTH / SHEAR_MODULUS
        self.plateau = mu * self.normal_force
        self.chi = self.plateau / self.peak

    def friction(self, u):
        x = min(u / self.u_star, 1.0)
        return self.plateau * (1 - (1 - x) ** 1.5)

    def stick_radius(self, u):
        return self.a * math.sqrt(max(1 - u / self.u_star, 0.0))

    def work(self, travel):
        assert travel >= self.u_star
        return SHEAR_MODULUS * self.a * self.u_c ** 2 + self.plateau * (
            travel - self.u_c - 0.4 * self.u_star * (1 - self.u_c / self.u_star) ** 2.5)


@pytest.fixture(scope="module", params=["below", "above"])
def case(request):
    scene = mdrsim.Scene.from_file(SCENES[request.param]).set("discretization.springs", SPRINGS)
    result = mdrsim.run(scene)
    mu = scene.to_dict()["friction"]["coefficient"]
    return request.param, result, Transition(mu)


def test_the_two_cases_are_the_two_scenarios():
    assert Transition(0.5).chi == pytest.approx(1 / math.sqrt(2), rel=1e-12)
    assert Transition(1.0).chi == pytest.approx(math.sqrt(2), rel=1e-12)


def test_the_glue_breaks_at_the_adhesive_peak(case):
    _, result, closed = case
    assert result.status == "completed" and result.sliding is False
    assert len(result.jumps) == 1
    jump = result.jumps[0]
    assert jump.by_shear and jump.stage == "shear" and jump.glued_springs == -SPRINGS
    # Under fixed grips at d = g(a_g) the row's N-th spring sits at a_g exactly: the peak and
    # u_c are the closed forms' to rounding (observed 2e-16).
    assert jump.critical.tangential_displacement == pytest.approx(closed.u_c, rel=1e-12)
    assert jump.critical.tangential_force == pytest.approx(closed.peak, rel=1e-12)
    assert jump.critical.springs_sliding == 0  # glued springs do not slide (unlimited glue)


def test_after_the_glue_breaks_the_force_drops_onto_cattaneo_mindlin(case):
    _, result, closed = case
    after = result.jumps[0].after
    # Every spring stays pressed; the row's sums over springs at spacing a/N: within 4/N mu F_z
    # as on loading (docs/friction.md; observed 0.71/N and 0.35/N).
    assert after.springs_in_contact == SPRINGS
    assert after.tangential_force == pytest.approx(closed.friction(closed.u_c),
                                                   abs=4 / SPRINGS * closed.plateau)
    assert after.tangential_force < result.jumps[0].critical.tangential_force  # always a drop
    assert after.stick_radius == pytest.approx(closed.stick_radius(closed.u_c),
                                               abs=2 * closed.a / SPRINGS)
    assert after.springs_sliding > 0


def test_then_it_slides_at_the_plateau_past_the_peak_only_for_chi_above_1(case):
    name, result, closed = case
    end = result.stages[-1].end
    assert end.springs_sliding == end.springs_in_contact == SPRINGS and end.stick_radius == 0.0
    assert end.tangential_force == pytest.approx(closed.mu * end.normal_force, rel=1e-12)
    # The row's F_z at d against Hertz's: a sum of the monotone line load E* (d - x^2/R) at
    # x_i = i dx is off its integral by at most dx times its variation, 2 E* d dx (both
    # halves), against F_z = (4/3) E* d a_g: within 1.5/N (observed 0.75/N).
    assert end.tangential_force == pytest.approx(closed.plateau, rel=1.5 / SPRINGS)
    assert (end.tangential_force > closed.peak) == (name == "above")
    # The tangential force rises monotonically from the drop to the plateau.
    t = result.trajectory
    jump_at = max(i for i, e in enumerate(t["event"]) if e == "jump")
    rising = t["tangential_force"][jump_at:]
    assert all(later >= earlier for earlier, later in zip(rising, rising[1:]))


def test_the_machines_work_is_the_glue_and_the_friction(case):
    _, result, closed = case
    shear = result.stages[-1]
    # Sums at spacing a/N, as above: within 4/N of itself (observed 0.56/N and 0.59/N).
    assert shear.work.tangential == pytest.approx(closed.work(TRAVEL), rel=4 / SPRINGS)
    # Friction dissipates less than the machine did: the rest went with the glue and stays as
    # the sticking springs' stretch, none of it negative.
    assert 0 < shear.work.dissipated_by_friction < shear.work.tangential
