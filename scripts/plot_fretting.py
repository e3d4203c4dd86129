#!/usr/bin/python3
"""Draws the engine's fretting loop against Cattaneo-Mindlin and Mindlin-Deresiewicz.

Run with Debian's Python, which has matplotlib:
    /usr/bin/python3 scripts/plot_fretting.py --results DIR [--springs 1000 10000]

Reads DIR/fretting_N.csv and DIR/fretting_N.json, what
    mdrsim run scenes/programs/fretting_parabola.toml --set discretization.springs=N \\
        --trajectory DIR/fretting_N.csv --json DIR/fretting_N.json
writes for each N (the main job, scripts/reproduce.sh, runs them): a sphere pressed with a
fixed normal load F_z, then moved tangentially under fixed grips to u_m, back to -u_m and up to
u_m again, under Coulomb friction mu. Draws DIR/fretting_loop.png and .svg: (a) F_x against
u_x, the engine's path at the finest N as lines and the closed forms as markers (loading
L(u) = mu F_z [1 - (1 - u/u*)^(3/2)], unloading L(u_m) - 2 L((u_m - u)/2), reloading -L(u_m) +
2 L((u_m + u)/2)); (b) the stick radius against u_x, the engine's beside a sqrt(1 - u/u*) on
loading and a sqrt(1 - (u_m - u)/(2 u*)) on unloading; (c) the deviation from the closed forms
along each branch at every N. Prints a table: the loop energy (the unload and reload stages'
tangential work) against W of Mindlin-Deresiewicz, F_x and the stick radius at the turning
point, the largest deviation along each branch, with the relative errors, at every N.

The closed forms (docs/friction.md "The closed forms the tests use") take the continuum's
contact at F_z: a = (3 F_z R / (4 E*))^(1/3), d = a^2/R, u* = mu E* d / G*. The row sums a line
load over springs at spacing dx = a/N and holds F_z with its own d, each off by O(1/N), so
every number is checked against a bound of that order: F_x within 4/N mu F_z (at the turning
point and along every branch), the loop energy within 4/N of itself, the stick radius within
2 dx (one spacing for the spring's place x_{j-1}, one for the row's a), and the frictional
work equal to the loop's work to rounding (a closed cycle dissipates all of it). Exits 1 if a
number is beyond its bound (a wrong number), 2 if the input is not such a fretting run; never
for timing.

The trajectory CSV has no stick radius column: on a monotone branch the sliding springs are
the outermost ones, so a row's stick radius is x_{n-s} = a_row (n - s)/n (x_i = i dx, n the
springs in contact, s the CSV's `sliding`); the script checks this against the JSON's
`stick_radius` at every stage end.
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

STAGES = ("press", "load", "unload", "reload")


class ClosedForms:
    """The parabola under Coulomb friction at the continuum's contact for F_z."""

    def __init__(self, radius, modulus, shear_modulus, mu, force, amplitude):
        self.values = (f"R = {radius:g} m, E* = {modulus:g} Pa, G* = {shear_modulus:g} Pa, "
                       f"mu = {mu:g}, F_z = {force:g} N")
        self.a = (3 * force * radius / (4 * modulus)) ** (1 / 3)
        self.d = self.a ** 2 / radius
        self.u_star = mu * modulus * self.d / shear_modulus
        self.limit = mu * force
        self.amplitude = amplitude

    def loading(self, u):
        x = min(abs(u) / self.u_star, 1.0)
        return math.copysign(self.limit * (1 - (1 - x) ** 1.5), u)

    def unloading(self, u):
        return self.loading(self.amplitude) - 2 * self.loading((self.amplitude - u) / 2)

    def reloading(self, u):
        return -self.loading(self.amplitude) + 2 * self.loading((self.amplitude + u) / 2)

    def branch(self, name, u):
        return {"load": self.loading, "unload": self.unloading, "reload": self.reloading}[name](u)

    def stick_radius(self, name, u):
        """Loading: a sqrt(1 - u/u*); unloading (reloading) from +-u_m: the springs slide
        back outside a sqrt(1 - |u_m -+ u|/(2 u*))."""
        slid = {"load": u, "unload": (self.amplitude - u) / 2,
                "reload": (self.amplitude + u) / 2}[name]
        return self.a * math.sqrt(max(1 - abs(slid) / self.u_star, 0.0))

    def loop_energy(self):
        xi = self.amplitude / self.u_star
        return self.limit * self.u_star * (4 * xi - 16 / 5 + 4 * xi * (1 - xi) ** 1.5
                                           + 16 / 5 * (1 - xi) ** 2.5)


def fail_input(message):
    print(f"plot_fretting: {message}", file=sys.stderr)
    sys.exit(2)


def read_run(results, springs):
    stem = os.path.join(results, f"fretting_{springs}")
    try:
        with open(stem + ".json") as f:
            result = json.load(f)
        with open(stem + ".csv", newline="") as f:
            rows = list(csv.DictReader(f))
    except OSError as e:
        fail_input(f"{e.filename}: {e.strerror} (run mdrsim run "
                   "scenes/programs/fretting_parabola.toml with --trajectory and --json)")
    if not rows or "sliding" not in rows[0]:
        fail_input(f"{stem}.csv has no 'sliding' column: is it a run with [friction]?")
    return result, rows


def closed_forms_of(result, path):
    """The scene's values, and a check that it is the fretting cycle the closed forms hold."""
    scene = result.get("scene", {})
    stages = scene.get("loading", {}).get("stage", [])
    if [s.get("name") for s in stages] != list(STAGES) or scene.get("profile", {}).get(
            "type") != "parabolic" or "friction" not in scene:
        fail_input(f"{path}: not the fretting cycle of scenes/programs/fretting_parabola.toml "
                   f"(stages {', '.join(STAGES)} on a parabola with [friction])")
    press, load, unload, reload = stages
    amplitude = load["tangential"]["by"]
    if (press["normal"]["control"] != "fixed-load" or unload["tangential"]["by"] != -2 * amplitude
            or reload["tangential"]["by"] != 2 * amplitude
            or scene["material"].get("work_of_adhesion", 0.0) != 0.0):
        fail_input(f"{path}: the closed forms need a non-adhesive sphere under a fixed load, "
                   "moved by u_m, -2 u_m and 2 u_m")
    material = result["material"]
    return ClosedForms(scene["profile"]["radius"], material["effective_modulus"],
                       material["effective_shear_modulus"], scene["friction"]["coefficient"],
                       press["normal"]["to"], amplitude)


def row_stick_radius(row):
    n = int(row["springs_in_contact"])
    return float(row["contact_radius"]) * (n - int(row["sliding"])) / n if n else 0.0


def branches(rows):
    """Per tangential stage, the rows that are equilibria of the row: (u, F_x, stick radius)."""
    out = {name: [] for name in STAGES[1:]}
    for r in rows:
        if r["stage"] in out and r["in_cascade"] == "0":
            out[r["stage"]].append((float(r["tangential_displacement"]),
                                    float(r["tangential_force"]), row_stick_radius(r)))
    return out


class Checks:
    """Every number beside its bound; `failed` once one is beyond it."""

    def __init__(self):
        self.failed = []

    def check(self, what, error, bound):
        if not error <= bound:
            self.failed.append(f"{what}: error {error:.3g} beyond its bound {bound:.3g}")
        return "ok" if error <= bound else "OFF"


def analyse(springs, result, rows, closed, checks):
    """The table's lines for one spring count, and its branches for the figure."""
    stages = {s["name"]: s for s in result["stages"]}
    path = branches(rows)
    # The CSV's stick radius, derived as above, against the JSON's at every stage end.
    last = {}
    for r in rows:
        last[r["stage"]] = r
    for name in STAGES:
        derived, reported = row_stick_radius(last[name]), stages[name]["end"]["stick_radius"]
        checks.check(f"N={springs} {name}: the CSV's stick radius against the JSON's",
                     abs(derived - reported) / closed.a, 1e-12)

    force_bound = 4 / springs  # of mu F_z
    lines = []

    def line(what, engine, exact, error, bound, unit):
        verdict = checks.check(f"N={springs} {what}", error, bound)
        values = ("" if engine is None else f"{engine:>13.6e} {exact:>13.6e} {unit}").ljust(30)
        lines.append(f"{springs:>6}  {what:<38} {values} {error:>9.2e} {error * springs:>7.3f} "
                     f"{bound:>8.1e}  {verdict}")

    work = sum(stages[n]["work"]["tangential"] for n in ("unload", "reload"))
    dissipated = sum(stages[n]["work"]["dissipated_by_friction"] for n in ("unload", "reload"))
    w = closed.loop_energy()
    line("loop energy W (unload + reload)", work, w, abs(work / w - 1), 4 / springs, "J")
    line("  of it dissipated by friction", dissipated, work, abs(dissipated / work - 1), 1e-12,
         "J")
    for name, u in (("load", closed.amplitude), ("unload", -closed.amplitude)):
        engine = stages[name]["end"]["tangential_force"]
        exact = closed.loading(u)
        line(f"F_x at u = {'+' if u > 0 else '-'}u_m ({name} end)", engine, exact,
             abs(engine / exact - 1), force_bound * closed.limit / abs(exact), "N")
    engine = stages["load"]["end"]["stick_radius"]
    exact = closed.stick_radius("load", closed.amplitude)
    line("stick radius at u_m", engine, exact, abs(engine / exact - 1),
         2 / springs * closed.a / exact, "m")
    for name in STAGES[1:]:
        worst = max(abs(f - closed.branch(name, u)) for u, f, _ in path[name])
        line(f"max |F_x - closed| / mu F_z, {name}", None, None, worst / closed.limit,
             force_bound, "")
    worst = max(abs(c - closed.stick_radius("load", u)) for u, _, c in path["load"])
    line("max |c - closed| / a, load", None, None, worst / closed.a, 2 / springs, "")
    return lines, path


def draw(paths, closed, out):
    finest = max(paths)
    um, mn = 1e6, 1e3
    fig, axes = plt.subplots(1, 3, figsize=(15.5, 4.8))
    colours = {"load": "tab:blue", "unload": "tab:red", "reload": "tab:green"}
    markers = {"load": "o", "unload": "s", "reload": "^"}
    labels = {"load": "loading (Cattaneo-Mindlin)", "unload": "unloading (Mindlin-Deresiewicz)",
              "reload": "reloading (Mindlin-Deresiewicz)"}
    spans = {"load": (0.0, closed.amplitude), "unload": (closed.amplitude, -closed.amplitude),
             "reload": (-closed.amplitude, closed.amplitude)}

    ax = axes[0]
    for name in STAGES[1:]:
        u = [p[0] * um for p in paths[finest][name]]
        f = [p[1] * mn for p in paths[finest][name]]
        ax.plot(u, f, color=colours[name], lw=1.6, label=f"engine, {labels[name].split()[0]}")
        lo, hi = spans[name]
        samples = [lo + (hi - lo) * k / 16 for k in range(17)]
        ax.plot([s * um for s in samples], [closed.branch(name, s) * mn for s in samples],
                markers[name], mfc="none", color=colours[name], ms=6, label=labels[name])
    for sign in (1, -1):
        ax.axhline(sign * closed.limit * mn, color="0.6", lw=0.8, ls=":")
    ax.text(closed.amplitude * um, closed.limit * mn * 0.96, r"$\mu F_z$ (full slip)",
            color="0.4", va="top", ha="right", fontsize=9)
    ax.set_xlabel(r"tangential displacement $u_x$ [$\mu$m]")
    ax.set_ylabel(r"tangential force $F_x$ [mN]")
    ax.set_title(f"(a) fretting loop, {finest} springs (lines) vs closed forms (markers)",
                 fontsize=10)
    ax.legend(fontsize=7.5, loc="upper left", bbox_to_anchor=(0.0, 0.93))
    ax.set_ylim(-1.08 * closed.limit * mn, 1.08 * closed.limit * mn)
    ax.grid(alpha=0.3)

    ax = axes[1]
    for name in STAGES[1:]:
        u = [p[0] * um for p in paths[finest][name]]
        c = [p[2] * um for p in paths[finest][name]]
        ax.plot(u, c, color=colours[name], lw=1.6, label=f"engine, {name}")
        lo, hi = spans[name]
        samples = [lo + (hi - lo) * k / 16 for k in range(17)]
        formula = {"load": r"$a\sqrt{1-u_x/u^*}$", "unload": r"$a\sqrt{1-(u_m-u_x)/2u^*}$",
                   "reload": r"$a\sqrt{1-(u_m+u_x)/2u^*}$"}[name]
        ax.plot([s * um for s in samples],
                [closed.stick_radius(name, s) * um for s in samples], markers[name], mfc="none",
                color=colours[name], ms=6, label=formula)
    ax.axhline(closed.a * um, color="0.6", lw=0.8, ls=":")
    ax.text(0.0, closed.a * um * 1.005, "contact radius a", color="0.4", fontsize=9, ha="center",
            va="bottom")
    ax.set_xlabel(r"tangential displacement $u_x$ [$\mu$m]")
    ax.set_ylabel(r"stick radius c [$\mu$m]")
    ax.set_title("(b) stick radius: engine (lines) vs closed forms (markers)", fontsize=10)
    ax.set_ylim(0.55 * closed.stick_radius("load", closed.amplitude) * um, 1.06 * closed.a * um)
    ax.legend(fontsize=7.5, loc="lower center", ncol=2)
    ax.grid(alpha=0.3)

    ax = axes[2]
    styles = ["-", "--", ":", "-."]
    for k, springs in enumerate(sorted(paths)):
        for name in STAGES[1:]:
            points = [(abs(closed.amplitude - u) if name != "load" else u, f, u)
                      for u, f, _ in paths[springs][name]]
            travel = [p[0] * um for p in points]
            error = [max(abs(f - closed.branch(name, u)) / closed.limit, 1e-9)
                     for _, f, u in points]
            ax.plot(travel, error, styles[k % 4], color=colours[name], lw=1.1,
                    label=f"{name}, N = {springs}")
        ax.axhline(4 / springs, color="0.3", lw=0.9, ls=styles[k % 4])
        ax.text(0.02, 4 / springs * 1.15, f"bound 4/N, N = {springs}", fontsize=8,
                transform=ax.get_yaxis_transform())
    ax.set_yscale("log")
    ax.set_ylim(1e-8, 3e-2)
    ax.set_xlabel(r"travel along the branch [$\mu$m] (from its turning point)")
    ax.set_ylabel(r"$|F_x - F_x^{closed}| / \mu F_z$")
    ax.set_title("(c) deviation from the closed forms: O(1/N)", fontsize=10)
    ax.legend(fontsize=7, ncol=2, loc="lower right")
    ax.grid(alpha=0.3, which="both")

    fig.suptitle("Fretting of a sphere under Coulomb friction (fretting_parabola.toml): "
                 f"{closed.values}, "
                 f"u_m = {closed.amplitude * um:g} um = {closed.amplitude / closed.u_star:.3f} u*",
                 fontsize=10.5)
    fig.tight_layout()
    for ext in ("png", "svg"):
        path = os.path.join(out, f"fretting_loop.{ext}")
        fig.savefig(path, dpi=130)
        print(f"wrote {path}")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--results", required=True,
                        help="folder of fretting_N.csv and .json; the figure goes there too")
    parser.add_argument("--springs", type=int, nargs="+", default=[1000, 10000])
    args = parser.parse_args()

    checks = Checks()
    table, paths, closed = [], {}, None
    for springs in args.springs:
        result, rows = read_run(args.results, springs)
        closed = closed_forms_of(result, os.path.join(args.results, f"fretting_{springs}.json"))
        lines, paths[springs] = analyse(springs, result, rows, closed, checks)
        table.extend(lines)

    print("Fretting loop (scenes/programs/fretting_parabola.toml) against Cattaneo-Mindlin and "
          "Mindlin-Deresiewicz")
    print(f"  a = {closed.a:.6e} m, u* = {closed.u_star:.6e} m, mu F_z = {closed.limit:.6e} N, "
          f"u_m = {closed.amplitude:.6e} m; bounds O(1/N): F_x 4/N mu F_z, W 4/N, c 2 dx;")
    print("  rel. err of F_x and c at u_m relative to their closed values, along a branch to "
          "mu F_z and a; err x N constant: first order")
    print(f"{'N':>6}  {'quantity':<38} {'engine':>13} {'closed form':>13} {'':<2} "
          f"{'rel. err':>9} {'err x N':>7} {'bound':>8}")
    for text in table:
        print(text)
    draw(paths, closed, args.results)
    if checks.failed:
        for text in checks.failed:
            print(f"OFF: {text}", file=sys.stderr)
        sys.exit(1)


if __name__ == "__main__":
    main()
