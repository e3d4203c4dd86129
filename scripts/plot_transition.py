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
line F_x = 2 G* a_g u up to u_c = sqrt(2 pi a_g dgamma / G*), where the glue breaks at
F_x,peak = 2 sqrt(2 pi dgamma G*) a_g^(3/2), then Cattaneo-Mindlin's L(u) = mu F_z [1 - (1 -
u/u*)^(3/2)], u* = mu E* d / G*, rising to mu F_z. Prints a table at every N: the peak, u_c,
the force just after the glue breaks, the plateau and the shear stage's work against the
closed forms, with relative errors and bounds. Exits 1 if a number is beyond its bound (a
wrong number), 2 if the input is not such a run; never for timing.

Bounds: the peak and u_c to rounding (the row's N-th spring sits at a_g exactly under fixed
grips at d = g(a_g)); the force after the break within 4/N mu F_z and the work within 4/N of
itself (sums of a line load over springs at spacing a_g/N); the plateau within 1.5/N (the row's
F_z against Hertz's: a sum of the monotone line load E* (d - x^2/R) at x_i = i dx is off its
integral by at most dx times its variation, 2 E* d dx both halves, against F_z = (4/3) E* d a_g).
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
        self.mu, self.depth, self.travel, self.shear_modulus = mu, depth, travel, shear_modulus
        self.a = math.sqrt(radius * depth)
        self.normal_force = 4 * modulus * self.a ** 3 / (3 * radius)
        self.u_c = math.sqrt(2 * math.pi * self.a * work / shear_modulus)
        self.peak = 2 * math.sqrt(2 * math.pi * work * shear_modulus) * self.a ** 1.5
        self.u_star = mu * modulus * depth / shear_modulus
        self.plateau = mu * self.normal_force
        self.chi = self.plateau / self.peak

    def force(self, u):
        """F_x on the path: glued up to u_c, Cattaneo-Mindlin after."""
        if u <= self.u_c:
            return 2 * self.shear_modulus * self.a * u
        return self.plateau * (1 - (1 - min(u / self.u_star, 1.0)) ** 1.5)

    def work(self):
        """The machine's tangential work to the end of the shear (past u*)."""
        tail = (1 - min(self.u_c / self.u_star, 1.0)) ** 2.5
        return self.shear_modulus * self.a * self.u_c ** 2 + self.plateau * (
            self.travel - self.u_c - 0.4 * self.u_star * tail)


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
    if closed.travel < closed.u_star:
        fail_input(f"{path}: the shear ends before full slip (u* = {closed.u_star:g} m)")
    return closed


def analyse(case, springs, result, closed, failed):
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
    rounding = 1e-12
    line("u_c (the glue breaks)", jump["critical"]["tangential_displacement"], closed.u_c,
         rounding * closed.u_c)
    line("F_x,peak", jump["critical"]["tangential_force"], closed.peak, rounding * closed.peak)
    line("F_x just after the break", jump["after"]["tangential_force"],
         closed.force(closed.u_c * (1 + 1e-15)), 4 / springs * closed.plateau)
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
        samples = [end * k / 24 for k in range(25)]
        glued = [s for s in samples if s < 1] + [1.0]
        slid = [1.0 + 1e-12] + [s for s in samples if s > 1]
        ax.plot(glued, [closed.force(s * closed.u_c) / closed.peak for s in glued], "o",
                mfc="none", color=colours[case], ms=5)
        ax.plot(slid, [closed.force(s * closed.u_c) / closed.peak for s in slid], "s",
                mfc="none", color=colours[case], ms=5)
        ax.axhline(closed.chi, color=colours[case], lw=0.8, ls=":")
        ax.text(end, closed.chi * 1.015, r"$\mu F_z$", color=colours[case], ha="right",
                va="bottom", fontsize=9)
    ax.plot([], [], "o", mfc="none", color="0.3",
            label=r"glued: $F_x = 2 G^* a_g u_x$ (the same for both)")
    ax.plot([], [], "s", mfc="none", color="0.3",
            label=r"after the break: Cattaneo-Mindlin $\mu F_z[1-(1-u_x/u^*)^{3/2}]$")
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
            table.extend(analyse(case, springs, result, closed, failed))
            paths[case] = (springs, rows)

    print("From adhesion to sliding friction (scenes/programs/adhesion_to_friction_chi_*.toml) "
          "against its closed forms")
    for case in CASES:
        c = closed_of[case]
        print(f"  chi {case} 1: mu = {c.mu:g}, chi = {c.chi:.6f}, a_g = {c.a:.6e} m, "
              f"u_c = {c.u_c:.6e} m, u* = {c.u_star:.6e} m, drop at the break "
              f"{1 - c.force(c.u_c * (1 + 1e-15)) / c.peak:.1%}, plateau/peak {c.chi:.3f}")
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
