"""The speed figure: the rate law's peak tension and a Prony solid's pull-off against speed.

The rate law of the edge (first panel): the peak tension of an elastic parabola retracted under
fixed grips from JKR's zero-force state (scenes/viscoelastic/rate_law_parabola.toml, continuum
route) against beta = (V / v*) (E* R / dgamma)^(1/3), for n = 1 and 1/2, from `mdrsim sweep` over
the retraction's speed, beside an independent solution of the front's ODE (scipy's solve_ivp at rtol
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

The Prony solid (second panel): a parabola pressed to d0 into an adhesive standard linear solid
and withdrawn at once at the same speed V until the contact is lost
(scenes/viscoelastic/prony_speed_pull_off.toml, the program row), swept over V tau / d0 from 1e-4
to 1e4 with both stages' speed linked. V tau / d0 is tau against the press's time d0 / V: much
slower, the arms relax as they go and carry one stress, and the pull-off is JKR's with (E_inf,
dgamma E_0 / E_inf); much faster, they stay glassy and it is JKR's with (E_0, dgamma)
(docs/viscoelastic.md "The adhesive edge", tests/engine/program/viscoelastic_adhesion_test.cpp).
The row's pull-off carries O(1/N): 0.75 / K* in those tests, K* = N a* / a_max the spring where
JKR's pull-off radius a* sits. The job fails where the slowest point is further than 1 / K* from
the slow limit, the fastest further than 1 / K* from the fast one, or |pull-off| rises with V.
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
# The Prony panel's V tau / d0: eight decades around the press lasting tau, three points a decade.
PRONY_SPEEDS = "1e-4:1e4:25:log"
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


class PronySolid:
    """The Prony scene's scales and limits: one Prony term on E*_inf, pressed to d0 and withdrawn
    at one speed (scenes/viscoelastic/prony_speed_pull_off.toml)."""

    def __init__(self, scene):
        material = scene["material"]
        relaxed = material.get("effective_modulus")
        if relaxed is None:
            relaxed = material["youngs_modulus"] / (1.0 - material.get("poisson_ratio", 0.0) ** 2)
            arms = [t["modulus"] / (1.0 - material.get("poisson_ratio", 0.0) ** 2)
                    for t in material["relaxation"]]
        else:
            arms = [t["modulus"] for t in material["relaxation"]]
        if len(arms) != 1:
            raise SystemExit(f"the Prony panel takes one Prony term, not {len(arms)}")
        self.tau = material["relaxation"][0]["time"]
        self.radius = scene["profile"]["radius"]
        self.dgamma = material["work_of_adhesion"]
        self.depth = scene["loading"]["stage"][0]["normal"]["to"]
        self.springs = scene["discretization"]["springs"]
        glassy = relaxed + arms[0]
        self.ratio = glassy / relaxed
        # JKR's pull-off -(3/2) pi R dgamma_eff and where it is reached, a* = (9 pi R^2
        # dgamma_eff / (8 E))^(1/3): slow (E_inf, dgamma E_0 / E_inf), fast (E_0, dgamma).
        self.limits = {}
        for name, modulus, dgamma in (("slow", relaxed, self.dgamma * glassy / relaxed),
                                      ("fast", glassy, self.dgamma)):
            radius = (9.0 * math.pi * self.radius**2 * dgamma / (8.0 * modulus)) ** (1.0 / 3.0)
            self.limits[name] = (-1.5 * math.pi * self.radius * dgamma, radius)
        # The row's springs span the largest contact radius (every spring glues on touch).
        self.contact = math.sqrt(self.radius * self.depth)

    def speed_scale(self):
        """d0 / tau: the press lasts d0 / V, so V tau / d0 is tau against the press's time."""
        return self.depth / self.tau

    def bound(self, name):
        """The row's O(1/N) bound on a limit's pull-off: 1 / K*, K* = N a* / a_max the spring
        where JKR's pull-off sits. The tests measured 0.75 / K* (1.01e-2 and 2.51e-3 at K* = 75
        and 299, 9.38e-3 and 2.33e-3 at K* = 79 and 317)."""
        return self.contact / (self.springs * self.limits[name][1])


def prony_pull_off(args):
    """The second panel's points: the Prony solid's pull-off (`peak_normal_force`) against both
    stages' speed V, swept over V tau / d0 = args.prony_speeds (RESULTS/prony_speed_pull_off.csv),
    printed against JKR's slow and fast limits, with the failures: the slowest point beyond the
    row's bound of the slow limit, the fastest beyond it of the fast limit, or |pull-off| rising
    with the speed (beyond 1e-12 of itself: the slow points agree to rounding)."""
    with open(args.prony_scene, "rb") as handle:
        solid = PronySolid(tomllib.load(handle))
    low, high, count, spacing = args.prony_speeds.split(":")
    scale = solid.speed_scale()
    speeds = f"{float(low) * scale!r}:{float(high) * scale!r}:{count}:{spacing}"
    path = os.path.join(args.results, "prony_speed_pull_off.csv")
    subprocess.run([args.mdrsim, "sweep", args.prony_scene, "--vary",
                    f"loading.stage.1.speed={speeds}", "--link", f"loading.stage.2.speed={speeds}",
                    "--csv", path, "--force", "--log-level", "error"], check=True)
    with open(path, newline="") as handle:
        text = "".join(line for line in handle if not line.startswith("#"))
    rows, failed = [], []
    for r in csv.DictReader(io.StringIO(text)):
        if not r["peak_normal_force"]:
            failed.append(f"Prony solid, V = {r['loading.stage.2.speed']} m/s: no pull-off "
                          f"(status {r['status']}, {r['stop_reason']})")
            continue
        rows.append({"speed": float(r["loading.stage.2.speed"]),
                     "pull_off": float(r["peak_normal_force"]), "status": r["status"]})
    rows.sort(key=lambda r: r["speed"])
    slow, fast = solid.limits["slow"][0], solid.limits["fast"][0]
    print(f"Prony solid, pull-off against V tau / d0 (d0 = {solid.depth:g} m, tau = "
          f"{solid.tau:g} s, {solid.springs} springs): slow limit {slow:.8e} N (bound "
          f"{solid.bound('slow'):.1e}), fast limit {fast:.8e} N (bound {solid.bound('fast'):.1e})")
    print(f"  {'V [m/s]':>10} {'V tau/d0':>10} {'pull-off [N]':>17} {'vs slow':>9} {'vs fast':>9}"
          f"  status")
    for r in rows:
        r["scaled"] = r["speed"] / scale
        print(f"  {r['speed']:10.3e} {r['scaled']:10.3e} {r['pull_off']:17.10e} "
              f"{abs(r['pull_off'] / slow - 1.0):9.2e} {abs(r['pull_off'] / fast - 1.0):9.2e}  "
              f"{r['status']}")
    for name, row, limit in (("slow", rows[0], slow), ("fast", rows[-1], fast)):
        error = abs(row["pull_off"] / limit - 1.0)
        bound = solid.bound(name)
        if not error <= bound:
            failed.append(f"Prony solid, the {name}est point (V = {row['speed']:.3e} m/s): "
                          f"pull-off {row['pull_off']!r} is {error:.2e} from its limit {limit!r} "
                          f"(> the row's bound {bound:.2e})")
    for before, after in zip(rows, rows[1:]):
        if not abs(after["pull_off"]) <= abs(before["pull_off"]) * (1.0 + 1e-12):
            failed.append(f"Prony solid: |pull-off| rises from {before['pull_off']!r} at V = "
                          f"{before['speed']:.3e} m/s to {after['pull_off']!r} at "
                          f"{after['speed']:.3e} m/s")
    return {"solid": solid, "rows": rows, "failed": failed}


def draw_prony_pull_off(axes, pull_off):
    """The second panel: the Prony solid's pull-off against V tau / d0 (`pull_off`, from
    prony_pull_off), with its slow limit (JKR with E_inf and dgamma E_0 / E_inf) and its fast
    limit (JKR with E_0) drawn."""
    solid, rows = pull_off["solid"], pull_off["rows"]
    scaled = [r["scaled"] for r in rows]
    (slow, _), (fast, _) = solid.limits["slow"], solid.limits["fast"]
    axes.axhline(-slow, color="C2", lw=0.8, ls="--",
                 label=f"slow limit: JKR (E_inf, dgamma E_0/E_inf), {-slow:.4e} N")
    axes.axhline(-fast, color="C3", lw=0.8, ls="--",
                 label=f"fast limit: JKR (E_0, dgamma), {-fast:.4e} N")
    axes.axvline(1.0, color="k", lw=0.6, ls=":", label="V = d0 / tau")
    axes.plot(scaled, [-r["pull_off"] for r in rows], "o", mfc="none", color="C0", ms=5,
              label=f"mdrsim, program row, {solid.springs} springs (O(1/N) <= "
                    f"{max(solid.bound('slow'), solid.bound('fast')):.0e})")
    axes.set_xscale("log")
    axes.set_yscale("log")
    axes.set_xlabel("V tau / d0 (press and withdrawal at V; d0 the press's depth)")
    axes.set_ylabel("pull-off -F_min [N]")
    axes.set_title(f"Standard linear solid (E_0 / E_inf = {solid.ratio:g}): pull-off against speed")
    axes.legend(fontsize=7)


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

    fig, axes = plt.subplots(1, 2, figsize=(12.8, 4.8), squeeze=False)
    draw_rate_law(axes[0][0], points)
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
    parser.add_argument("--prony-scene", default="scenes/viscoelastic/prony_speed_pull_off.toml")
    parser.add_argument("--prony-speeds", default=PRONY_SPEEDS,
                        help="V tau / d0 as FROM:TO:COUNT:log (default %(default)s)")
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
    pull_off = prony_pull_off(args)
    failed += pull_off["failed"]
    draw(points, pull_off, args.results)
    for line in failed:
        print(f"FAIL {line}")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
