"""The rate law of the edge: the peak tension of an elastic parabola retracted under fixed grips
from JKR's zero-force state (scenes/viscoelastic/rate_law_parabola.toml, continuum route)
against beta = (V / v*) (E* R / dgamma)^(1/3), for n = 1 and 1/2, from `mdrsim sweep` over the
retraction's speed, beside an independent solution of the front's ODE (scipy's solve_ivp at rtol
1e-10; no number of the engine), the slow limit (JKR's fixed-grips pull-off, -F0) and the fast
asymptote derived below. Draws RESULTS/rate_law_speed.png and exits 1 where an engine point is
further than 1e-6 (relative) from the reference, or a point at beta >= 100 further from the fast
asymptote than its correction's bound.

The fast asymptote. In the units of docs/rate_law.md (a = L alpha, d = (L^2 / R) delta, t = (L /
v*) tau, F = dgamma R f, L = (dgamma R^2 / E*)^(1/3)) the front obeys

    d alpha / d tau = -max(G - 1, 0)^(1/n),   G = (alpha^2 - delta)^2 / (2 pi alpha),
    delta = delta0 - beta tau,   f = 2 (delta alpha - alpha^3 / 3),

from alpha0^3 = 9 pi / 2. For beta -> infinity the grips pull far (|delta| >> alpha^2, delta0,
G >> 1) before the front has moved: delta ~ -beta tau, and with tau = beta^(-2/(n+2)) sigma the
front's ODE loses beta, d alpha / d sigma = -(sigma^2 / (2 pi alpha))^(1/n), while f = -2
beta^(n/(n+2)) alpha sigma. Its solution is closed: alpha^((n+1)/n) = alpha0^((n+1)/n) - k
sigma^((n+2)/n), k = (n+1) / (n+2) (2 pi)^(-1/n), and alpha sigma is largest at

    alpha* = alpha0 ((n+2) / (2n+3))^(n/(n+1)),
    sigma* = alpha0^((n+1)/(n+2)) ((n+2) / (2n+3))^(n/(n+2)) (2 pi)^(1/(n+2)),

so F_peak / F0 -> -(4 / (3 pi)) alpha* sigma* beta^(n/(n+2)) (F0 = 3 pi dgamma R / 2): beta^(1/3)
for n = 1, beta^(1/5) for n = 1/2. What was dropped (delta0 and alpha^2 beside beta tau, alpha^3/3
in f, the 1 in G - 1) is of relative order beta^(-n/(n+2)): the points at beta >= 100 must lie
within ASYMPTOTE_BOUND beta^(-n/(n+2)) of it, relative.
"""

import argparse
import csv
import io
import math
import os
import subprocess
import sys
import tomllib

from scipy.integrate import solve_ivp

# The engine against the reference: both at rtol 1e-10; 1e-6 leaves room for the event location
# and the reference's own global error, and still tells any mistake in the law.
REFERENCE_TOLERANCE = 1e-6
# |1 - F / F_asymptote| <= ASYMPTOTE_BOUND beta^(-n/(n+2)) at beta >= 100: the dropped terms'
# order; their coefficient, measured from the reference up to beta = 1e10, approaches 4/3 for
# n = 1 and 1.15 for n = 1/2 from below.
ASYMPTOTE_BOUND = 1.5
FAST = 100.0
EXPONENTS = (1.0, 0.5)
# Two points a decade; beyond 1e6 the engine stops the walk (the front "stopped on its way to the
# axis") at n = 1 from beta = 1e7.
BETAS = "1e-4:1e6:21:log"
POWER_TEXT = {1.0: "1/3", 0.5: "1/5"}  # n / (n + 2)
ALPHA0 = (4.5 * math.pi) ** (1.0 / 3.0)  # JKR's zero-force state
F0 = 1.5 * math.pi  # in units of dgamma R


def reference_peak(beta, n):
    """F_peak / F0 of the front's ODE (the module docstring), solved by DOP853 at rtol 1e-10 to
    the first zero of dF/dtau = 2 (-beta alpha + (delta - alpha^2) d alpha / d tau), where the
    tension stops growing."""
    delta0 = ALPHA0**2 - math.sqrt(2.0 * math.pi * ALPHA0)

    def front(tau, y):
        alpha, delta = y
        excess = (delta - alpha * alpha) ** 2 / (2.0 * math.pi * alpha) - 1.0
        return [-max(excess, 0.0) ** (1.0 / n), -beta]

    def slope(tau, y):
        alpha, delta = y
        return -beta * alpha + (delta - alpha * alpha) * front(tau, y)[0]

    slope.terminal, slope.direction = True, 1.0
    # The peak comes at tau of order beta^(-2/(n+2)) when fast; when slow, once the grips have
    # moved by delta ~ 1, at tau ~ 1 / beta.
    span = 1.0 / beta if beta < 1.0 else beta ** (-2.0 / (n + 2.0))
    while True:
        s = solve_ivp(front, (0.0, 10.0 * span), [ALPHA0, delta0], method="DOP853", rtol=1e-10,
                      atol=1e-14, events=slope)
        if s.t_events[0].size:
            alpha, delta = s.y_events[0][0]
            return 2.0 * (delta * alpha - alpha**3 / 3.0) / F0
        if s.status != 0:
            raise RuntimeError(f"reference at beta = {beta}, n = {n}: {s.message}")
        span *= 10.0


def fast_asymptote(beta, n):
    """-(4 / (3 pi)) alpha* sigma* beta^(n/(n+2)): the module docstring."""
    shrink = (n + 2.0) / (2.0 * n + 3.0)
    alpha = ALPHA0 * shrink ** (n / (n + 1.0))
    sigma = (ALPHA0 ** ((n + 1.0) / (n + 2.0)) * shrink ** (n / (n + 2.0))
             * (2.0 * math.pi) ** (1.0 / (n + 2.0)))
    return -2.0 * alpha * sigma * beta ** (n / (n + 2.0)) / F0


class Parabola:
    """The scene's scales: v* and beta per unit retraction speed, (E* R / dgamma)^(1/3) / v*."""

    def __init__(self, scene):
        material = scene["material"]
        modulus = material.get("effective_modulus")
        if modulus is None:
            modulus = material["youngs_modulus"] / (1.0 - material.get("poisson_ratio", 0.0) ** 2)
        self.speed_star = scene["detachment"]["front_speed_law"]["speed"]
        self.per_speed = (modulus * scene["profile"]["radius"] / material["work_of_adhesion"]) ** (
            1.0 / 3.0) / self.speed_star

    def speeds(self, betas):
        """`--vary` values of the retraction's speed for a beta range FROM:TO:COUNT:log."""
        low, high, count, spacing = betas.split(":")
        return f"{float(low) / self.per_speed!r}:{float(high) / self.per_speed!r}:{count}:{spacing}"


def engine_sweep(mdrsim, scene, parabola, n, betas, results):
    """The sweep's CSV rows over the retraction's speed at exponent n, written to
    RESULTS/rate_law_speed_n{n}.csv."""
    speeds = parabola.speeds(betas)
    law = f"detachment.front_speed_law={{speed={parabola.speed_star!r}, exponent={n!r}}}"
    path = os.path.join(results, f"rate_law_speed_n{n:g}.csv")
    subprocess.run([mdrsim, "sweep", scene, "--set", law, "--vary",
                    f"loading.stage.2.speed={speeds}", "--csv", path, "--force", "--log-level",
                    "error"], check=True)
    with open(path, newline="") as handle:
        text = "".join(line for line in handle if not line.startswith("#"))
    return list(csv.DictReader(io.StringIO(text)))


def prony_pull_off(args):
    """The second panel's points: a Prony solid's pull-off against the retraction's speed, from
    a sweep of the adhesive edge under a relaxing bulk (docs/viscoelastic.md). None while the
    engine refuses that scene (work_of_adhesion > 0 with relaxation): the figure then has the
    rate law's panel alone."""
    del args
    return None


def draw_prony_pull_off(axes, pull_off):
    """The second panel: the Prony solid's pull-off against speed (`pull_off`, from
    prony_pull_off), with its slow limit (JKR with E_inf and dgamma E_0 / E_inf) and its fast
    limit (JKR with E_0) drawn."""
    raise NotImplementedError("the Prony solid's pull-off against speed is not drawn yet")


def draw_rate_law(axes, points):
    """The rate law's panel: the engine's points, the reference through the same betas, the
    slow limit and the fast asymptote."""
    styles = {1.0: ("C0", "o"), 0.5: ("C1", "s")}
    for n, rows in points.items():
        color, marker = styles[n]
        betas = [r["beta"] for r in rows]
        axes.plot(betas, [-r["reference"] for r in rows], "-", color=color, lw=1,
                  label=f"front ODE (solve_ivp), n = {n:g}")
        fast = [b for b in betas if b >= 1.0]
        axes.plot(fast, [-fast_asymptote(b, n) for b in fast], "--", color=color, lw=0.8,
                  label=f"fast asymptote ~ beta^({POWER_TEXT[n]}), n = {n:g}")
        axes.plot(betas, [-r["engine"] for r in rows], marker, mfc="none", color=color, ms=5,
                  label=f"mdrsim, continuum route, n = {n:g}")
    axes.axhline(1.0, color="k", lw=0.8, ls=":", label="slow limit: JKR fixed grips, -F0")
    axes.set_xscale("log")
    axes.set_yscale("log")
    axes.set_xlabel("beta = (V / v*) (E* R / dgamma)^(1/3)")
    axes.set_ylabel("peak tension -F_peak / F0")
    axes.set_title("Rate law of the edge: peak tension against retraction speed")
    axes.legend(fontsize=7)


def draw(points, pull_off, results):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    panels = 1 if pull_off is None else 2
    fig, axes = plt.subplots(1, panels, figsize=(6.4 * panels, 4.8), squeeze=False)
    draw_rate_law(axes[0][0], points)
    if pull_off is not None:
        draw_prony_pull_off(axes[0][1], pull_off)
    fig.tight_layout()
    for ext in ("png", "svg"):
        fig.savefig(os.path.join(results, f"rate_law_speed.{ext}"))
    print(f"wrote {os.path.join(results, 'rate_law_speed.png')}")
    plt.close(fig)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--results", default="results")
    parser.add_argument("--mdrsim", default="build/apps/mdrsim")
    parser.add_argument("--scene", default="scenes/viscoelastic/rate_law_parabola.toml")
    parser.add_argument("--betas", default=BETAS, help="FROM:TO:COUNT:log (default %(default)s)")
    args = parser.parse_args()
    with open(args.scene, "rb") as handle:
        scene = tomllib.load(handle)
    parabola = Parabola(scene)
    os.makedirs(args.results, exist_ok=True)
    failed, points = [], {}
    print("rate law, peak tension F/F0 against beta: engine (continuum), reference, asymptote")
    for n in EXPONENTS:
        rows = []
        for row in engine_sweep(args.mdrsim, args.scene, parabola, n, args.betas, args.results):
            beta = float(row["loading.stage.2.speed"]) * parabola.per_speed
            engine = float(row["dimensionless_peak_normal_force"])
            reference = reference_peak(beta, n)
            asymptote = fast_asymptote(beta, n)
            error = abs(engine / reference - 1.0)
            rows.append({"beta": beta, "engine": engine, "reference": reference})
            correction = abs(1.0 - engine / asymptote) * beta ** (n / (n + 2.0))
            print(f"  n = {n:g}  beta = {beta:9.3e}  F/F0 = {engine:+.10f}  reference "
                  f"{reference:+.10f}  error {error:.1e}  asymptote {asymptote:+.6f}  "
                  f"|1 - F/F_asym| beta^(n/(n+2)) = {correction:.4f}  dissipated_at_front "
                  f"{float(row['dissipated_at_front']):.6e} J")
            if not error <= REFERENCE_TOLERANCE:
                failed.append(f"n = {n:g}, beta = {beta:.3e}: F/F0 {engine!r} is {error:.1e} "
                              f"from the reference {reference!r} (> {REFERENCE_TOLERANCE:.0e})")
            if beta >= FAST and not correction <= ASYMPTOTE_BOUND:
                failed.append(f"n = {n:g}, beta = {beta:.3e}: {engine!r} is off the fast "
                              f"asymptote {asymptote!r} by {correction:.3f} beta^(-n/(n+2)) "
                              f"(> {ASYMPTOTE_BOUND})")
        points[n] = rows
        last, before = rows[-1], rows[-3]
        slope = math.log(last["engine"] / before["engine"]) / math.log(last["beta"] / before["beta"])
        print(f"  n = {n:g}: the engine's d ln|F| / d ln beta over its last decade {slope:.4f}, "
              f"the asymptote's n/(n+2) = {n / (n + 2.0):.4f}")
    draw(points, prony_pull_off(args), args.results)
    for line in failed:
        print(f"FAIL {line}")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
