#!/usr/bin/env python3
"""Closed-form reference of Popov, Lyashenko & Filippov (MDR adhesion under tangential load).

An independent implementation of the paper's analytic results, in plain Python with
the math module only (no numpy, no call into the C++ engine), so that the figures and the
comparison table test the engine against something it does not share code with.

Dimensionless units (paper eq. 16-17): a~ = a/a0, d~ = d/d0, F~ = F/F0, u~ = ux/d0 with
    F0 = 3/2 pi R dgamma,  a0 = (9 pi R^2 dgamma / (8 E*))^(1/3),
    d0 = (3 pi^2 R dgamma^2 / (64 E*^2))^(1/3).
gamma = G*/E* = (2 - 2 nu)/(2 - nu) (eq. 9); the paper's figures use nu = 0, gamma = 1.

Equations implemented:
    eq. 18-19  JKR branch             d~ = 3a~^2 - 4 a~^(1/2),  F~ = a~^3 - 2 a~^(3/2)
    eq. 25-27  with tangential u~     d~ = 3a~^2 - sqrt(16 a~ - gamma u~^2)
                                      F~z = a~/2 (d~ - a~^2),   F~x = gamma/2 a~ u~
    eq. 29     fixed-load critical radius (largest root, a~ > gamma u~^2/16)
    eq. 31-33  fixed-grips critical radius and forces
    eq. 34-35  fixed-grips master curve F~z = F~x^2/(4 gamma) - 5/9

Note: the paper's text says the fixed-grips pull-off of the pure normal contact is
F~ = -0.5; its own eq. 33 (a~^3 = 1/9) gives -5/9, which is the correct value.

Run it as a script for a self-check and a short table of reference values.
"""

import math

# Root-finding tolerance on the (dimensionless) contact radius.
ROOT_TOL = 1e-14


# --------------------------------------------------------------------------- units

def effective_moduli(youngs_modulus, poisson_ratio):
    """E*, G* of paper eq. 8 for a rigid indenter on an elastic half-space."""
    e, nu = youngs_modulus, poisson_ratio
    g = e / (2.0 * (1.0 + nu))
    return e / (1.0 - nu * nu), 4.0 * g / (2.0 - nu)


def gamma_from_nu(poisson_ratio):
    """gamma = G*/E* = (2 - 2 nu)/(2 - nu), paper eq. 9."""
    return (2.0 - 2.0 * poisson_ratio) / (2.0 - poisson_ratio)


def scales(radius, effective_modulus, work_of_adhesion):
    """(F0, a0, d0) of paper eq. 17 for the parabola f = r^2/(2R)."""
    r, es, dg = radius, effective_modulus, work_of_adhesion
    f0 = 1.5 * math.pi * r * dg
    a0 = (9.0 * math.pi * r * r * dg / (8.0 * es)) ** (1.0 / 3.0)
    d0 = (3.0 * math.pi ** 2 * r * dg ** 2 / (64.0 * es ** 2)) ** (1.0 / 3.0)
    return f0, a0, d0


# --------------------------------------------------------------------------- equilibrium branch

def jkr_indentation(a):
    """Eq. 18: d~(a~) of the JKR branch (no tangential displacement)."""
    return 3.0 * a * a - 4.0 * math.sqrt(a)


def jkr_force(a):
    """Eq. 19: F~(a~) of the JKR branch."""
    return a ** 3 - 2.0 * a ** 1.5


def indentation(a, u, gamma=1.0):
    """Eq. 25: d~(a~) with tangential displacement u~ (requires 16 a~ >= gamma u~^2)."""
    arg = 16.0 * a - gamma * u * u
    if arg < 0.0:
        raise ValueError(f"a~ = {a} below the shear-off radius gamma u~^2/16 = {gamma * u * u / 16}")
    return 3.0 * a * a - math.sqrt(arg)


def normal_force(a, d):
    """Eq. 26: F~z = a~/2 (d~ - a~^2)."""
    return 0.5 * a * (d - a * a)


def tangential_force(a, u, gamma=1.0):
    """Eq. 27: F~x = gamma/2 a~ u~."""
    return 0.5 * gamma * a * u


def state(a, u, gamma=1.0):
    """The equilibrium state (eq. 25-27) at contact radius a~ and tangential displacement u~."""
    d = indentation(a, u, gamma)
    return {"a": a, "d": d, "Fz": normal_force(a, d), "Fx": tangential_force(a, u, gamma), "u": u}


# --------------------------------------------------------------------------- roots

def bisect(func, lo, hi, tol=ROOT_TOL):
    """Root of func in [lo, hi] (func(lo), func(hi) of opposite signs) by bisection."""
    flo, fhi = func(lo), func(hi)
    if flo == 0.0:
        return lo
    if fhi == 0.0:
        return hi
    if (flo > 0.0) == (fhi > 0.0):
        raise ValueError(f"root not bracketed in [{lo}, {hi}]: f = {flo}, {fhi}")
    for _ in range(400):
        mid = 0.5 * (lo + hi)
        if hi - lo <= tol * max(1.0, abs(mid)) or mid in (lo, hi):
            break
        fmid = func(mid)
        if fmid == 0.0:
            return mid
        if (fmid > 0.0) == (flo > 0.0):
            lo, flo = mid, fmid
        else:
            hi = mid
    return 0.5 * (lo + hi)


def fixed_load_condition(a, u, gamma=1.0):
    """Left-hand side of eq. 29: a~^2 sqrt(a~ - gamma u~^2/16) - a~ + gamma u~^2/24 (= 0 at dF~z/da~ = 0)."""
    c = gamma * u * u / 16.0
    return a * a * math.sqrt(max(a - c, 0.0)) - a + gamma * u * u / 24.0


def critical_radius_fixed_load(u, gamma=1.0):
    """Eq. 29: critical radius under fixed normal load (fixed-grips tangential).

    The contact shrinks from a large radius during pull-off, so the instability is the
    first point where dF~z/da~ = 0 met from above: the largest root on a~ > gamma u~^2/16.
    At a~ = gamma u~^2/16 the condition is -gamma u~^2/48 < 0 and at a~ = c + 2 it is
    positive, so a root exists; a fine scan guards against several sign changes.
    """
    c = gamma * u * u / 16.0
    lo, hi = c, c + 2.0
    if u == 0.0:
        lo = 1e-300  # a~ = 0 is a trivial root of eq. 29 at u~ = 0; the physical one is a~ = 1
    f = lambda a: fixed_load_condition(a, u, gamma)
    n = 4000
    grid = [lo + (hi - lo) * i / n for i in range(n + 1)]
    values = [f(a) for a in grid]
    for i in range(n, 0, -1):  # the last sign change from - to +
        if values[i - 1] <= 0.0 < values[i]:
            return bisect(f, grid[i - 1], grid[i])
    raise RuntimeError(f"eq. 29 has no root for u~ = {u}, gamma = {gamma}")


def fixed_grips_condition(a, u, gamma=1.0):
    """Left-hand side of eq. 31: a~^3 - gamma/16 (u~ a~)^2 - 1/9 (= 0 at dd~/da~ = 0)."""
    return a ** 3 - gamma / 16.0 * (u * a) ** 2 - 1.0 / 9.0


def critical_radius_fixed_grips(u, gamma=1.0):
    """Eq. 31: critical radius under fixed normal grips. The cubic has exactly one positive
    root and it lies in (c, c + 1), c = gamma u~^2/16 (p(c) = -1/9, p(c + 1) > 0)."""
    c = gamma * u * u / 16.0
    return bisect(lambda a: fixed_grips_condition(a, u, gamma), c, c + 1.0)


# --------------------------------------------------------------------------- critical points

def critical_fixed_load(u, gamma=1.0):
    """Critical state under fixed-load normal and fixed-grips tangential control (eq. 29, 25-27)."""
    return state(critical_radius_fixed_load(u, gamma), u, gamma)


def critical_fixed_grips(u, gamma=1.0):
    """Critical state under fixed-grips normal and tangential control (eq. 31-33).

    Forces from eq. 32-33 (F~x taken with the sign of u~); eq. 25-27 give the same values.
    """
    a = critical_radius_fixed_grips(u, gamma)
    fx2 = 4.0 * gamma * (a ** 3 - 1.0 / 9.0)                    # eq. 32
    fx = math.copysign(math.sqrt(max(fx2, 0.0)), u)
    fz = a ** 3 - 2.0 / 3.0                                      # eq. 33
    return {"a": a, "d": indentation(a, u, gamma), "Fz": fz, "Fx": fx, "u": u}


def critical(control, u, gamma=1.0):
    """Critical state for normal control 'fixed-load' or 'fixed-grips'."""
    if control == "fixed-load":
        return critical_fixed_load(u, gamma)
    if control == "fixed-grips":
        return critical_fixed_grips(u, gamma)
    raise ValueError(f"unknown control {control!r}")


def master_curve_fixed_grips(fx, gamma=1.0):
    """Eq. 34 (eq. 35 for gamma = 1): F~z = F~x^2/(4 gamma) - 5/9 under fixed grips."""
    return fx * fx / (4.0 * gamma) - 5.0 / 9.0


def reversible_cycle():
    """A reversible-JKR approach-retract cycle under fixed grips (beyond the paper: loading
    programs). The contact jumps in at d~ = 0 onto eq. 18-19's branch (a~^3 = 16/9, F~ = -8/9),
    follows it both ways, and jumps out at the fold dd~/da~ = 0 (a~^3 = 1/9, F~ = -5/9). The
    machine's work over the cycle is the area between the branch and F~ = 0 from d~_c to 0:
    W~ = -integral F~ dd~ over a~ from a~_c to a~_0, by composite Simpson on 20000 intervals.
    Returns (jump-in force, fold force, dissipated work in F0 d0)."""
    a0, ac = (16.0 / 9.0) ** (1.0 / 3.0), (1.0 / 9.0) ** (1.0 / 3.0)
    n = 20000
    h = (a0 - ac) / n

    def integrand(a):
        return jkr_force(a) * (6.0 * a - 2.0 / math.sqrt(a))  # F~ dd~/da~

    total = integrand(ac) + integrand(a0)
    for i in range(1, n):
        total += (4.0 if i % 2 else 2.0) * integrand(ac + i * h)
    work = -total * h / 3.0
    return jkr_force(a0), jkr_force(ac), work


JKR_PULL_OFF_FIXED_LOAD = -1.0        # eq. 19 at a~ = 1
JKR_PULL_OFF_FIXED_GRIPS = -5.0 / 9.0  # eq. 33 at u~ = 0 (the text's -0.5 is a slip)


# --------------------------------------------------------------------------- self-check

def _self_check():
    problems = []

    def expect(name, got, want, tol=1e-12):
        if not abs(got - want) <= tol:
            problems.append(f"{name}: {got!r} != {want!r}")

    # Pure normal contact.
    expect("fixed-load pull-off", critical_fixed_load(0.0)["Fz"], -1.0)
    expect("fixed-load a_c", critical_fixed_load(0.0)["a"], 1.0)
    expect("fixed-load d_c", critical_fixed_load(0.0)["d"], -1.0)
    expect("fixed-grips pull-off", critical_fixed_grips(0.0)["Fz"], -5.0 / 9.0)
    expect("fixed-grips a_c", critical_fixed_grips(0.0)["a"], (1.0 / 9.0) ** (1.0 / 3.0))
    expect("eq. 25 = eq. 18 at u = 0", indentation(0.7, 0.0), jkr_indentation(0.7))
    expect("eq. 26 = eq. 19 at u = 0", normal_force(0.7, indentation(0.7, 0.0)), jkr_force(0.7))
    for nu in (0.0, 0.3, 0.5):
        gamma = gamma_from_nu(nu)
        es, gs = effective_moduli(1e6, nu)
        expect(f"gamma(nu={nu})", gs / es, gamma)
        for i in range(0, 81):
            u = 0.05 * i
            fg = critical_fixed_grips(u, gamma)
            direct = state(fg["a"], u, gamma)   # eq. 25-27 at the eq. 31 radius
            expect(f"eq. 33 vs 26, u={u}, nu={nu}", fg["Fz"], direct["Fz"], 1e-11)
            expect(f"eq. 32 vs 27, u={u}, nu={nu}", fg["Fx"], direct["Fx"], 1e-11)
            expect(f"eq. 34, u={u}, nu={nu}", fg["Fz"], master_curve_fixed_grips(fg["Fx"], gamma), 1e-11)
            fl = critical_fixed_load(u, gamma)
            # dF~z/da~ = 0 at the fixed-load radius (numerical derivative of eq. 25-26)
            h = 1e-6
            dfda = (state(fl["a"] + h, u, gamma)["Fz"] - state(fl["a"] - h, u, gamma)["Fz"]) / (2 * h)
            expect(f"dFz/da = 0, u={u}, nu={nu}", dfda, 0.0, 1e-7)
            # dd~/da~ = 0 at the fixed-grips radius
            ddda = (indentation(fg["a"] + h, u, gamma) - indentation(fg["a"] - h, u, gamma)) / (2 * h)
            expect(f"dd/da = 0, u={u}, nu={nu}", ddda, 0.0, 1e-7)
            # the fixed-load instability comes first (larger radius, more negative or equal force)
            if not fl["a"] >= fg["a"] - 1e-12:
                problems.append(f"u={u}, nu={nu}: fixed-load radius {fl['a']} < fixed-grips {fg['a']}")
    # Scales: R = 1 cm, E* = 1 MPa, dgamma = 0.05 (the scenes' values)
    f0, a0, d0 = scales(0.01, 1e6, 0.05)
    expect("d0", d0, 2.2614848269449475e-6, 1e-20)
    expect("a0", a0, 2.6046985393390237e-4, 1e-17)
    return problems


def main():
    problems = _self_check()
    print("paper_reference: closed forms of Popov, Lyashenko & Filippov (dimensionless)")
    print(f"  JKR pull-off: fixed-load {JKR_PULL_OFF_FIXED_LOAD:+.6f}, fixed-grips {JKR_PULL_OFF_FIXED_GRIPS:+.6f}")
    print(f"  {'u~':>5} | {'fixed-load a~ d~ F~z F~x':>44} | {'fixed-grips a~ d~ F~z F~x':>44}")
    for u in (0.0, 0.5, 1.0, 2.0, 3.0, 4.0):
        fl, fg = critical_fixed_load(u), critical_fixed_grips(u)
        row = lambda s: f"{s['a']:10.6f} {s['d']:10.6f} {s['Fz']:10.6f} {s['Fx']:10.6f}"
        print(f"  {u:5.2f} | {row(fl)} | {row(fg)}")
    if problems:
        print("SELF-CHECK FAILED:")
        for p in problems[:20]:
            print("  " + p)
        return 1
    print("  self-check passed")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
