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
    length: F_x = 2 G* a_g u. The edge (no normal force, no friction limit) lets go where
    G* u^2 = 2 pi a_g dgamma, at u_c, F_x,peak = 2 G* a_g u_c. Inside, friction holds mu (E*/G*)
    (d - g(x)) of a pressed spring's stretch once unglued, and only the rest pays the surface
    (docs/friction.md "Letting go under friction"): the front at c lets go at u(c) = mu (E*/G*)
    (d - g(c)) + sqrt(2 pi c dgamma / G*), the springs outside it sliding at their limits,
    F_x(c) = 2 [G* c u(c) + mu E* int_c^a (d - g) dx]. The glue peels while u(c) rises as c
    falls, and the rest breaks where u(c) is largest, at c*^(3/2) = R/(4 mu) sqrt(2 pi dgamma /
    G*) (E* = G*), past u* = mu E* d / G*: every spring then slides, F_x = mu F_z."""

    def __init__(self, mu):
        self.mu = mu
        self.a = math.sqrt(RADIUS * DEPTH)
        self.normal_force = 4 * MODULUS * self.a ** 3 / (3 * RADIUS)
        self.u_c = math.sqrt(2 * math.pi * self.a * WORK / SHEAR_MODULUS)
        self.peak = 2 * math.sqrt(2 * math.pi * WORK * SHEAR_MODULUS) * self.a ** 1.5
        self.u_star = mu * MODULUS * DEPTH / SHEAR_MODULUS
        self.plateau = mu * self.normal_force
        self.chi = self.plateau / self.peak
        self.c_break = (RADIUS / (4 * mu) * math.sqrt(2 * math.pi * WORK / SHEAR_MODULUS)) ** (2 / 3)

    def u_at(self, c):
        return (self.mu * MODULUS / SHEAR_MODULUS * (self.a ** 2 - c ** 2) / RADIUS
                + math.sqrt(2 * math.pi * c * WORK / SHEAR_MODULUS))

    def force_at(self, c):
        a = self.a
        return 2 * (SHEAR_MODULUS * c * self.u_at(c)
                    + self.mu * MODULUS / RADIUS * (a * a * (a - c) - (a ** 3 - c ** 3) / 3))

    def work(self, travel):
        """G* a_g u_c^2, the peeling's integral of F_x du (Simpson in c, 2000 intervals), and
        the plateau from the break to `travel`."""
        n, c0, c1 = 2000, self.a, self.c_break
        h = (c1 - c0) / n

        def slope(c):  # du/dc
            return (-2 * self.mu * MODULUS / SHEAR_MODULUS * c / RADIUS
                    + 0.5 * math.sqrt(2 * math.pi * WORK / (SHEAR_MODULUS * c)))

        peel = sum((1 if i in (0, n) else 4 if i % 2 else 2)
                   * self.force_at(c0 + i * h) * slope(c0 + i * h) for i in range(n + 1)) * h / 3
        u_break = self.u_at(c1)
        assert travel >= u_break
        return SHEAR_MODULUS * self.a * self.u_c ** 2 + peel + self.plateau * (travel - u_break)


@pytest.fixture(scope="module", params=["below", "above"])
def case(request):
    scene = mdrsim.Scene.from_file(SCENES[request.param]).set("discretization.springs", SPRINGS)
    result = mdrsim.run(scene)
    mu = scene.to_dict()["friction"]["coefficient"]
    return request.param, result, Transition(mu)


def test_the_two_cases_are_the_two_scenarios():
    assert Transition(0.5).chi == pytest.approx(1 / math.sqrt(2), rel=1e-12)
    assert Transition(1.0).chi == pytest.approx(math.sqrt(2), rel=1e-12)


def test_the_glue_peels_past_the_adhesive_peak_and_breaks_where_u_is_largest(case):
    _, result, closed = case
    assert result.status == "completed" and result.sliding is False
    assert len(result.jumps) == 1
    jump = result.jumps[0]
    assert jump.stage == "shear"
    # The front moves by spacings along a branch flat at its fold: u and F_x within 2/N
    # (observed 2e-7 and 8e-4 at 1000 springs).
    u_break = closed.u_at(closed.c_break)
    assert jump.critical.tangential_displacement == pytest.approx(u_break, rel=2 / SPRINGS)
    assert jump.critical.tangential_force == pytest.approx(closed.force_at(closed.c_break),
                                                           rel=2 / SPRINGS)
    assert u_break > closed.u_star  # every spring slides after the break
    assert jump.after.springs_sliding == jump.after.springs_in_contact == SPRINGS


def test_then_it_slides_at_the_plateau(case):
    _, result, closed = case
    end = result.stages[-1].end
    assert end.springs_sliding == end.springs_in_contact == SPRINGS and end.stick_radius == 0.0
    assert end.tangential_force == pytest.approx(closed.mu * end.normal_force, rel=1e-12)
    # The row's F_z at d against Hertz's: a sum of the monotone line load E* (d - x^2/R) at
    # x_i = i dx is off its integral by at most dx times its variation, 2 E* d dx (both
    # halves), against F_z = (4/3) E* d a_g: within 1.5/N (observed 0.75/N).
    assert end.tangential_force == pytest.approx(closed.plateau, rel=1.5 / SPRINGS)


def test_the_machines_work_is_the_glue_the_peeling_and_the_friction(case):
    _, result, closed = case
    shear = result.stages[-1]
    # Sums at spacing a/N, as above: within 4/N of itself.
    assert shear.work.tangential == pytest.approx(closed.work(TRAVEL), rel=4 / SPRINGS)
    assert 0 < shear.work.dissipated_by_friction < shear.work.tangential
