#!/usr/bin/python3
"""Draws the transition from adhesion to sliding friction against its closed forms.

Run with Debian's Python, which has matplotlib:
    /usr/bin/python3 scripts/plot_transition.py --results DIR [--springs 1000 10000]

Reads DIR/transition_CASE_N.csv and .json for CASE in below, above, what
    mdrsim run scenes/programs/adhesion_to_friction_chi_CASE.toml \\
        --set discretization.springs=N --trajectory DIR/transition_CASE_N.csv \\
        --json DIR/transition_CASE_N.json
writes (the main job, scripts/reproduce.sh, runs them): a sphere glued on touch at a_g with its
edge unstretched (fixed grips at d = a_g^2/R), then sheared under fixed grips, under Coulomb
friction with chi = mu F_z / F_x,peak below and above 1. Draws DIR/friction_transition.png and
.svg: F_x / F_x,peak against u_x / u_c for both, the engine's path at the finest N as lines,
the closed forms as markers (docs/friction.md "From adhesion to sliding friction"): the glued
line F_x = 2 G* a_g u up to u_c = sqrt(2 pi a_g dgamma / G*), where the edge lets go at the
adhesive peak F_x,peak = 2 sqrt(2 pi dgamma G*) a_g^(3/2); then the glue peels, its front at c
letting go at u(c) = mu (E*/G*) (d - g(c)) + sqrt(2 pi c dgamma / G*) with F_x(c) = 2 [G* c u(c)
+ mu E* int_c^a_g (d - g) dx], and the rest breaks where u(c) is largest, at c*^(3/2) = (G* R /
(4 mu E*)) sqrt(2 pi dgamma / G*), onto the plateau mu F_z (where c* >= a_g the glue breaks
whole at u_c and Cattaneo-Mindlin's L(u) = mu F_z [1 - (1 - u/u*)^(3/2)], u* = mu E* d / G*,
follows). Prints a table at every N: the break's u and F_x, the largest F_x, the force just
after the break, the plateau and the shear stage's work against the closed forms, with relative
errors and bounds. Exits 1 if a number is beyond its bound (a wrong number), 2 if the input is
not such a run; never for timing.

Bounds: the break's u and F_x within 2/N (the row's front moves by spacings along a branch flat
at its fold), the largest F_x along the peeling within 2/N; the force after the break and the
plateau within 1.5/N (the row's F_z against Hertz's: a sum of the monotone line load E* (d -
x^2/R) at x_i = i dx is off its integral by at most dx times its variation, 2 E* d dx both
halves, against F_z = (4/3) E* d a_g); the work within 4/N of itself (sums of a line load over
springs at spacing a_g/N). Where the glue breaks whole at u_c, u_c and F_x,peak to rounding.
"""

import argparse
import csv
import json
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

CASES = ("below", "above")


class Transition:
    """The closed forms of the glued parabola sheared under fixed grips with friction."""

    def __init__(self, radius, modulus, shear_modulus, work, depth, mu, travel):
        self.radius, self.modulus, self.shear_modulus, self.dgamma = (radius, modulus,
                                                                      shear_modulus, work)
        self.mu, self.depth, self.travel = mu, depth, travel
        self.a = math.sqrt(radius * depth)
        self.normal_force = 4 * modulus * self.a ** 3 / (3 * radius)
        self.u_c = math.sqrt(2 * math.pi * self.a * work / shear_modulus)
        self.peak = 2 * math.sqrt(2 * math.pi * work * shear_modulus) * self.a ** 1.5
        self.u_star = mu * modulus * depth / shear_modulus
        self.plateau = mu * self.normal_force
        self.chi = self.plateau / self.peak
        # Where u(c) is largest: du/dc = 0.
        scale = shear_modulus * radius / (4 * mu * modulus) if mu > 0 else math.inf
        self.c_break = min((scale * math.sqrt(2 * math.pi * work / shear_modulus)) ** (2 / 3),
                           self.a)
        self.peels = self.c_break < self.a

    def u_at(self, c):
        """The u_x at which the glued front at c lets go."""
        return (self.mu * self.modulus / self.shear_modulus * (self.a ** 2 - c ** 2) / self.radius
                + math.sqrt(2 * math.pi * c * self.dgamma / self.shear_modulus))

    def force_at(self, c):
        """F_x with the front at c: the glue at u(c), the springs outside it at their limits."""
        a = self.a
        return 2 * (self.shear_modulus * c * self.u_at(c) + self.mu * self.modulus / self.radius
                    * (a * a * (a - c) - (a ** 3 - c ** 3) / 3))

    def fronts(self, n):
        """n + 1 fronts from a_g to c*, equally spaced in c."""
        return [self.a + (self.c_break - self.a) * i / n for i in range(n + 1)]

    def u_break(self):
        return self.u_at(self.c_break) if self.peels else self.u_c

    def force_break(self):
        return self.force_at(self.c_break) if self.peels else self.peak

    def largest_force(self):
        """The largest F_x before the break (along the peeling, 4000 fronts: well within 1/N)."""
        if not self.peels:
            return self.peak
        return max(self.force_at(c) for c in self.fronts(4000))

    def force_after(self, u):
        """F_x after the break: every spring slides where it broke past u*, else
        Cattaneo-Mindlin's loading from the unglued contact."""
        if self.peels:
            return self.plateau
        return self.plateau * (1 - (1 - min(u / self.u_star, 1.0)) ** 1.5)

    def work(self):
        """The machine's tangential work to the end of the shear: the glued line to u_c, the
        peeling's integral of F_x du (Simpson in c, 2000 intervals) and the plateau after the
        break (past u*), or Cattaneo-Mindlin's after a whole break."""
        glued = self.shear_modulus * self.a * self.u_c ** 2
        if not self.peels:
            tail = (1 - min(self.u_c / self.u_star, 1.0)) ** 2.5
            return glued + self.plateau * (self.travel - self.u_c - 0.4 * self.u_star * tail)
        n = 2000
        h = (self.c_break - self.a) / n

        def slope(c):  # du/dc
            return (-2 * self.mu * self.modulus / self.shear_modulus * c / self.radius
                    + 0.5 * math.sqrt(2 * math.pi * self.dgamma / (self.shear_modulus * c)))

        peel = sum((1 if i in (0, n) else 4 if i % 2 else 2) * self.force_at(c) * slope(c)
                   for i, c in enumerate(self.fronts(n))) * h / 3
        return glued + peel + self.plateau * (self.travel - self.u_break())


def fail_input(message):
    print(f"plot_transition: {message}", file=sys.stderr)
    sys.exit(2)


def read_run(results, case, springs):
    stem = os.path.join(results, f"transition_{case}_{springs}")
    try:
        with open(stem + ".json") as f:
            result = json.load(f)
        with open(stem + ".csv", newline="") as f:
            rows = list(csv.DictReader(f))
    except OSError as e:
        fail_input(f"{e.filename}: {e.strerror} (run mdrsim run "
                   f"scenes/programs/adhesion_to_friction_chi_{case}.toml with --trajectory and "
                   "--json)")
    return result, rows


def closed_forms_of(result, path):
    scene = result.get("scene", {})
    stages = scene.get("loading", {}).get("stage", [])
    try:
        glue, shear = stages
        ok = (glue["normal"]["control"] == "fixed-grips" and "to" in glue["normal"]
              and shear["tangential"]["control"] == "fixed-grips" and "normal" not in shear
              and scene["profile"]["type"] == "parabolic" and "friction" in scene
              and scene["material"]["work_of_adhesion"] > 0)
    except (KeyError, ValueError, TypeError):
        ok = False
    if not ok:
        fail_input(f"{path}: not a glued parabola sheared under fixed grips with friction "
                   "(scenes/programs/adhesion_to_friction_chi_*.toml)")
    m = result["material"]
    closed = Transition(scene["profile"]["radius"], m["effective_modulus"],
                        m["effective_shear_modulus"], m["work_of_adhesion"], glue["normal"]["to"],
                        scene["friction"]["coefficient"], shear["tangential"]["by"])
    if closed.travel < max(closed.u_star, closed.u_break()):
        fail_input(f"{path}: the shear ends before full slip (u* = {closed.u_star:g} m, the "
                   f"break at {closed.u_break():g} m)")
    return closed


def analyse(case, springs, result, rows, closed, failed):
    lines = []

    def line(what, engine, exact, bound_abs):
        error = abs(engine - exact)
        verdict = "ok" if error <= bound_abs else "OFF"
        if verdict == "OFF":
            failed.append(f"chi {case} 1, N={springs}, {what}: {engine:.6e} against "
                          f"{exact:.6e}, beyond {bound_abs:.1e}")
        lines.append(f"{case:>5} {closed.chi:6.3f} {springs:>6}  {what:<28} {engine:>13.6e} "
                     f"{exact:>13.6e} {error / abs(exact):>9.2e} {bound_abs / abs(exact):>8.1e}"
                     f"  {verdict}")

    jumps = result["jumps"]
    if result["status"] != "completed" or len(jumps) != 1 or not jumps[0]["by_shear"]:
        failed.append(f"chi {case} 1, N={springs}: expected one jump by shear and the status "
                      f"completed, got {len(jumps)} jump(s), {result['status']}")
        return lines
    jump, end = jumps[0], result["stages"][-1]
    if closed.peels:
        line("u_x at the break", jump["critical"]["tangential_displacement"], closed.u_break(),
             2 / springs * closed.u_break())
        line("F_x at the break", jump["critical"]["tangential_force"], closed.force_break(),
             2 / springs * closed.force_break())
    else:
        rounding = 1e-12
        line("u_c (the glue breaks)", jump["critical"]["tangential_displacement"], closed.u_c,
             rounding * closed.u_c)
        line("F_x,peak", jump["critical"]["tangential_force"], closed.peak, rounding * closed.peak)
    largest = max(float(r["tangential_force"]) for r in rows
                  if float(r["tangential_displacement"]) <= jump["critical"]["tangential_displacement"])
    line("largest F_x before the break", largest, closed.largest_force(),
         2 / springs * closed.largest_force())
    line("F_x just after the break", jump["after"]["tangential_force"],
         closed.force_after(closed.u_break() * (1 + 1e-15)), 1.5 / springs * closed.plateau)
    line("plateau mu F_z", end["end"]["tangential_force"], closed.plateau,
         1.5 * closed.plateau / springs)
    line("work of the shear stage", end["work"]["tangential"], closed.work(),
         4 / springs * closed.work())
    return lines


def draw(paths, closed_of, out):
    fig, ax = plt.subplots(figsize=(7.6, 5.0))
    colours = {"below": "tab:blue", "above": "tab:red"}
    for case in CASES:
        closed = closed_of[case]
        springs, rows = paths[case]
        u = [float(r["tangential_displacement"]) / closed.u_c for r in rows]
        f = [float(r["tangential_force"]) / closed.peak for r in rows]
        ax.plot(u, f, color=colours[case], lw=1.6,
                label=f"engine, $\\chi$ = {closed.chi:.3f} ($\\mu$ = {closed.mu:g}), "
                      f"{springs} springs")
        end = closed.travel / closed.u_c
        glued = [k / 8 for k in range(9)]
        ax.plot(glued, [2 * closed.shear_modulus * closed.a * s * closed.u_c / closed.peak
                        for s in glued], "o", mfc="none", color=colours[case], ms=5)
        if closed.peels:
            fronts = closed.fronts(12)
            ax.plot([closed.u_at(c) / closed.u_c for c in fronts],
                    [closed.force_at(c) / closed.peak for c in fronts], "^", mfc="none",
                    color=colours[case], ms=5)
        start = closed.u_break() / closed.u_c
        slid = [start + (end - start) * k / 8 for k in range(9)]
        slid[0] *= 1 + 1e-12
        ax.plot(slid, [closed.force_after(s * closed.u_c) / closed.peak for s in slid], "s",
                mfc="none", color=colours[case], ms=5)
        ax.axhline(closed.chi, color=colours[case], lw=0.8, ls=":")
        ax.text(end, closed.chi * 1.015, r"$\mu F_z$", color=colours[case], ha="right",
                va="bottom", fontsize=9)
    ax.plot([], [], "o", mfc="none", color="0.3",
            label=r"glued: $F_x = 2 G^* a_g u_x$ (the same for both)")
    ax.plot([], [], "^", mfc="none", color="0.3",
            label=r"peeling: front at $c$ lets go at $u(c)$, $F_x(c)$")
    ax.plot([], [], "s", mfc="none", color="0.3",
            label=r"after the break at $\max_c u(c)$: every spring slides, $\mu F_z$")
    ax.axhline(1.0, color="0.5", lw=0.8, ls="--")
    ax.text(0.05, 1.015, r"adhesive peak $F_{x,peak} = 2\sqrt{2\pi\Delta\gamma G^*}\,a_g^{3/2}$",
            color="0.35", fontsize=8.5, va="bottom")
    ax.set_xlabel(r"tangential displacement $u_x / u_c$,  $u_c = \sqrt{2\pi a_g \Delta\gamma/G^*}$")
    ax.set_ylabel(r"tangential force $F_x / F_{x,peak}$")
    ax.set_title("From adhesion to sliding friction: a glued sphere sheared under fixed grips\n"
                 r"(adhesion_to_friction_chi_*.toml; $\chi = \mu F_z / "
                 r"F_{x,peak}$; lines engine, markers closed forms)", fontsize=9.5)
    ax.set_ylim(0, 1.25 * max(1.0, max(c.chi for c in closed_of.values())))
    ax.legend(fontsize=7.5, loc="lower right")
    ax.grid(alpha=0.3)
    fig.tight_layout()
    for ext in ("png", "svg"):
        path = os.path.join(out, f"friction_transition.{ext}")
        fig.savefig(path, dpi=130)
        print(f"wrote {path}")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--results", required=True,
                        help="folder of transition_CASE_N.csv and .json; the figure goes there")
    parser.add_argument("--springs", type=int, nargs="+", default=[1000, 10000])
    args = parser.parse_args()

    failed, table, paths, closed_of = [], [], {}, {}
    for case in CASES:
        for springs in sorted(args.springs):
            result, rows = read_run(args.results, case, springs)
            closed = closed_forms_of(result, f"transition_{case}_{springs}.json")
            closed_of[case] = closed
            table.extend(analyse(case, springs, result, rows, closed, failed))
            paths[case] = (springs, rows)

    print("From adhesion to sliding friction (scenes/programs/adhesion_to_friction_chi_*.toml) "
          "against its closed forms")
    for case in CASES:
        c = closed_of[case]
        print(f"  chi {case} 1: mu = {c.mu:g}, chi = {c.chi:.6f}, a_g = {c.a:.6e} m, "
              f"u_c = {c.u_c:.6e} m, u* = {c.u_star:.6e} m, breaks at c* = {c.c_break:.6e} m, "
              f"u = {c.u_break():.6e} m, F_x = {c.force_break():.6e} N, drop at the break "
              f"{1 - c.force_after(c.u_break() * (1 + 1e-15)) / c.force_break():.1%}, "
              f"plateau/peak {c.chi:.3f}")
    print(f"{'chi':>5} {'':>6} {'N':>6}  {'quantity':<28} {'engine':>13} {'closed form':>13} "
          f"{'rel. err':>9} {'bound':>8}")
    for text in table:
        print(text)
    draw(paths, closed_of, args.results)
    if failed:
        for text in failed:
            print(f"OFF: {text}", file=sys.stderr)
        sys.exit(1)


if __name__ == "__main__":
    main()
