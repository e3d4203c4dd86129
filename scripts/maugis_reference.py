"""Maugis' adhesive parabola with a Dugdale zone, in his own variables: the main job's yardstick
for finite-range adhesion, written apart from the engine (no MDR, no Abel transform).

Maugis (J. Colloid Interface Sci. 150, 1992), for f(r) = r^2/(2R) on E* with the Dugdale stress
sigma_0 over the gap h0 = w / sigma_0 (w the work of adhesion): K = 4 E*/3,
lambda = 2 sigma_0 (R / (pi w K^2))^(1/3), a = A (pi w R^2/K)^(1/3), c = m a,
delta = D (pi^2 w^2 R/K^2)^(1/3), F = P pi w R. With t = arccos(1/m):
  (lambda A^2/2) [tan t + (m^2 - 2) t] + (4 lambda^2 A/3) [t tan t - m + 1] = 1,
  P = A^3 - lambda A^2 [tan t + m^2 t],   D = A^2 - (4/3) A lambda tan t.
Once the contact has closed (A = 0) the disk of radius C = c (K/(pi w R^2))^(1/3) pulls alone:
P = -(pi lambda/2) C^2, D = C^2/2 - (8 lambda/(3 pi)) C - 2/(pi lambda); the contact branch meets
it at C0, the root of (pi lambda/4) C^2 + (4 lambda^2/3)(pi/2 - 1) C = 1.
"""

import math

from scipy.optimize import brentq, minimize_scalar

def _zone(y):
    """m, tan t and t at y = ln m, each to full precision at both ends (m -> 1 and m -> inf)."""
    tan_t = math.sqrt(math.expm1(2.0 * y))
    return math.exp(y), tan_t, math.atan(tan_t)


def _opening(y, big_a, lam):
    m, tan_t, t = _zone(y)
    return (lam * big_a**2 / 2.0 * (tan_t + (m * m - 2.0) * t)
            + 4.0 * lam**2 * big_a / 3.0 * (t * tan_t - m + 1.0) - 1.0)


def contact_state(lam, big_a):
    """(P, D, m) on the contact branch at A > 0."""
    hi = 1.0
    while _opening(hi, big_a, lam) < 0.0:
        hi *= 2.0
    y = brentq(_opening, 0.0, hi, args=(big_a, lam), xtol=1e-300, rtol=1e-15, maxiter=500)
    m, tan_t, t = _zone(y)
    force = big_a**3 - lam * big_a**2 * (tan_t + m * m * t)
    depth = big_a**2 - 4.0 / 3.0 * big_a * lam * tan_t
    return force, depth, m


def closing_radius(lam):
    """C0: where the contact closes onto the no-contact branch."""
    qa = math.pi * lam / 4.0
    qb = 4.0 * lam**2 / 3.0 * (math.pi / 2.0 - 1.0)
    return (-qb + math.sqrt(qb * qb + 4.0 * qa)) / (2.0 * qa)


def free_state(lam, big_c):
    """(P, D) of the no-contact branch at C."""
    return (-math.pi * lam / 2.0 * big_c**2,
            big_c**2 / 2.0 - 8.0 * lam / (3.0 * math.pi) * big_c - 2.0 / (math.pi * lam))


def _first_minimum(value, lam):
    """The first local minimum of value(A) going down the contact branch from a large contact,
    as (A, value); None where value still falls as A -> 0."""
    top = max(4.0, 2.0 * lam)
    grid = [top * (1e-5 / top) ** (k / 1500.0) for k in range(1501)]
    values = [value(a) for a in grid]
    # A rise below the rounding of the roots (about 1e-12 of the value) is no minimum.
    for k in range(1, len(grid) - 1):
        rise = 1e-11 * (1.0 + abs(values[k]))
        if values[k] <= values[k - 1] and values[k] + rise < values[k + 1]:
            # The root of the slope (central differences of step 1e-5 A: truncation ~1e-10,
            # rounding ~1e-11), not the minimum of the values (good to sqrt(eps) in A only).
            def slope(a, step=1e-5):
                return (value(a * (1.0 + step)) - value(a * (1.0 - step))) / (2.0 * step * a)

            lo, hi = grid[k + 1], grid[k - 1]
            if slope(lo) < 0.0 < slope(hi):
                at = brentq(slope, lo, hi, xtol=1e-300, rtol=1e-14)
            else:  # too flat for the slope's rounding: the minimum of the values
                at = minimize_scalar(value, bracket=(lo, grid[k], hi), method="brent",
                                     tol=1e-12).x
            return at, value(at)
    return None


def fixed_load_pull_off(lam):
    """P at the fixed-load pull-off: the first minimum of P going down, or the closing point."""
    found = _first_minimum(lambda a: contact_state(lam, a)[0], lam)
    if found is not None:
        return found[1]
    return free_state(lam, closing_radius(lam))[0]


def fixed_grips_jump(lam):
    """(P, D) of the last equilibrium before the fixed-grips jump: where the contact closes first
    (lambda <= grips_threshold()), the no-contact branch's fold at C = 8 lambda/(3 pi); else the
    first minimum of D going down the contact branch (within 1e-5 of A = 0, just above the
    threshold, the closing point: their P differ by O(A^2))."""
    if lam <= grips_threshold():
        return free_state(lam, 8.0 * lam / (3.0 * math.pi))
    found = _first_minimum(lambda a: contact_state(lam, a)[1], lam)
    if found is None:
        return free_state(lam, closing_radius(lam))
    force, depth, _ = contact_state(lam, found[0])
    return force, depth


def grips_threshold():
    """The lambda below which the fixed-grips jump leaves from the no-contact branch: where C0
    reaches that branch's fold 8 lambda/(3 pi), lambda^3 = 9 pi / (16 (pi - 1))."""
    return (9.0 * math.pi / (16.0 * (math.pi - 1.0))) ** (1.0 / 3.0)


def _self_check():
    """Maugis' limits and the lambda = 1 value his paper tabulates."""
    assert abs(fixed_load_pull_off(1e3) + 1.5) < 2e-2, fixed_load_pull_off(1e3)
    assert abs(fixed_load_pull_off(1e-3) + 2.0) < 1e-2, fixed_load_pull_off(1e-3)
    assert abs(fixed_load_pull_off(1.0) + 1.6007) < 1e-4, fixed_load_pull_off(1.0)
    assert abs(fixed_grips_jump(1e3)[0] + 5.0 / 6.0) < 1e-3, fixed_grips_jump(1e3)
    lam = grips_threshold()
    assert abs(closing_radius(lam) - 8.0 * lam / (3.0 * math.pi)) < 1e-12
    # The contact branch's D rises from A = 0 below the threshold and falls just above it.
    for side, rises in ((1.0 - 1e-3, True), (1.0 + 1e-3, False)):
        d_small, d_smaller = contact_state(lam * side, 1e-3)[1], contact_state(lam * side, 1e-4)[1]
        assert (d_small > d_smaller) == rises, (side, d_small, d_smaller)


if __name__ == "__main__":
    _self_check()
    for lam in (0.01, 0.1, 0.5, 1.0, 2.0, 10.0, 100.0):
        print(f"{lam:8g} {fixed_load_pull_off(lam):.10f} {fixed_grips_jump(lam)[0]:.10f}")
    print("threshold", grips_threshold())
