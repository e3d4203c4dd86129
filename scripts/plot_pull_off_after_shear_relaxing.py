#!/usr/bin/python3
"""Draws the pull-off force after a prior shear on a relaxing bulk, at three shear speeds and two holds.

Run with Debian's Python, which has matplotlib:
    /usr/bin/python3 scripts/plot_pull_off_after_shear_relaxing.py --results DIR

Reads what the main job (scripts/reproduce.sh) writes:
    DIR/pull_off_after_shear_relaxing.csv   mdrsim sweep
        scenes/viscoelastic/pull_off_after_shear_relaxing.toml
        --vary loading.stage.4.tangential.to=0:4u_c:17
        --vary loading.stage.4.speed=u_c/(100 tau),u_c/tau,100 u_c/tau
        --vary loading.stage.5.duration=1e-3,10 --vary loading.rebinding=false,true
    DIR/pull_off_after_shear_2000.csv   (optional) the elastic program's sweep, drawn beside it
The scene is scenes/programs/pull_off_after_shear.toml's sphere on a standard linear solid
(E_0 = 10 E_inf, tau = 1 s, G_j = E_j G*/E*): glued on touch, pressed and relaxed, sheared to u
at a speed, held, pulled off. u is in units of the elastic scene's u_c (with G*_inf). The glue
lets go on the glassy criterion: sheared slowly it holds to sqrt(E_0/E_inf) u_c, sheared fast
(faster than u_c / tau) to u_c / sqrt(E_0/E_inf) (docs/friction.md "Pull-off after shear on a
relaxing bulk"). Prints the table (pull-off / unsheared pull-off against u/u_c for each speed,
hold and rebinding) and compares it with closed forms (exit 1 on a miss, printing what it
compared; exit 2 on input that is not such a sweep):
- the unsheared pull-off of every curve, F(a_g) with F(a) = 4 E_inf a^3/(3R) - sqrt(8 pi a^3
  dgamma E_0), a_g = sqrt(R d_max) the glued radius (glued on touch at the deepest press);
- after a hold of 10 tau (every arm relaxed, e^-10), the whole curve: the relaxed retraction's
  least force along the stable peel with the shear's load G_inf u in the glassy criterion;
- without rebinding, the glue breaks during the shear (status shear-off) exactly above the
  shear u_b(V) where G_inf u + G_1 V tau (1 - e^(-u/(V tau))) = sqrt(2 pi a_g dgamma G_0): near
  sqrt(E_0/E_inf) u_c slowly, near u_c sqrt(E_inf/E_0) fast;
- nothing pulls harder than the unsheared contact (1e-2).
The first two hold to the row's first-order error in its spacing, 0.62/N of the unsheared
pull-off measured at N = 1000 .. 8000; the tolerance is 1/N of it. Draws
DIR/pull_off_after_shear_relaxing.png and .svg.
"""

import argparse
import csv
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

MODULUS = 1.0e6  # E*_inf = G*_inf [Pa]
ARM_MODULUS = 9.0e6  # E*_1 = G*_1 [Pa]
GLASSY = MODULUS + ARM_MODULUS  # E_0 = G_0 [Pa]
WORK = 0.05  # dgamma [J/m^2]
RADIUS = 0.01  # R [m]
PRESS_DEPTH = 2.74092e-5  # the press's deepest point, 12.12 d0 [m]
HELD_DEPTH = 2.713781792333937e-5  # eased to 12 d0 [m]
GLUED_RADIUS = 5.209397078678047e-4  # a_g = 2 a0 of the relaxed material [m]
U_C = math.sqrt(2 * math.pi * GLUED_RADIUS * WORK / MODULUS)  # [m]
TAU = 1.0  # [s]
RELAXED_HOLD = 10.0  # a hold after which every arm is relaxed (e^-10) [s]
SHEAR_KEY = "loading.stage.4.tangential.to"
SPEED_KEY = "loading.stage.4.speed"
HOLD_KEY = "loading.stage.5.duration"
ELASTIC_KEY = "loading.stage.2.tangential.to"


def read_rows(path, required):
    try:
        with open(path, newline="") as f:
            lines = [line for line in f if not line.startswith("#")]
    except OSError as e:
        print(f"plot_pull_off_after_shear_relaxing: cannot read {path}: {e.strerror}",
              file=sys.stderr)
        sys.exit(2)
    rows = list(csv.DictReader(lines))
    if not rows or any(key not in rows[0] for key in required):
        print(f"plot_pull_off_after_shear_relaxing: {path} is not the expected sweep",
              file=sys.stderr)
        sys.exit(2)
    return rows


def pull_off(row):
    """The most tensile force of the retraction [N] (peak_normal_force), 0 where nothing pulled."""
    text = row["peak_normal_force"]
    return -float(text) if text else 0.0


def speed_label(speed):
    return f"{speed * TAU / U_C:g} u_c/tau"


# The closed forms. Glued on touch, the glue reaches a_g = sqrt(R d_max) at the deepest press
# and holds as the press eases; 20 tau later every arm is relaxed. From then on every glued
# spring moves with the depth d(t), so its arms carry one load S(t) common to all of them:
# q_z(x) = E_inf (D - x^2/R) with D = d + S/E_inf, and the force of a glue of radius a is
# F = 2 E_inf (D a - a^3/(3R)). The edge lets go on the glassy criterion q_z^2/E_0 + q_x^2/G_0 =
# 2 pi a dgamma; relaxed, q_x = G_inf u, and G_0/G_inf = E_0/E_inf, so at a let-go
# F(a, u) = 4 E_inf a^3/(3R) - 2a sqrt(2 pi a dgamma E_0 - E_inf G_inf u^2), whatever the pull's
# speed (S drops out). D falls monotonically under the pull, so the peel runs from a_g inwards
# while D(a) = a^2/R - sqrt(...)/E_inf grows with a (stable) and cascades where it stops; the
# pull-off is the least F along the stable peel, 0 if it never pulls. At u = 0 F(a) falls with
# a up to a* = 5.6e-4 m > a_g, so the unsheared pull-off is F(a_g, 0).
GLUED_RADIUS_PRESSED = math.sqrt(RADIUS * PRESS_DEPTH)


def relaxed_let_go_force(a, u):
    """F(a, u) at the let-go of a relaxed glue of radius a under the shear u [N].

    None where the shear alone breaks it.
    """
    load = 2 * math.pi * a * WORK * GLASSY - MODULUS * MODULUS * u * u
    if load <= 0.0:
        return None
    return 4 * MODULUS * a**3 / (3 * RADIUS) - 2 * a * math.sqrt(load)


def relaxed_pull_off(u, steps=20000):
    """The least force along the stable relaxed peel from a_g after the shear u [N].

    0 if it never pulls.
    """
    least = 0.0
    h = GLUED_RADIUS_PRESSED / steps
    for i in range(steps):
        a = GLUED_RADIUS_PRESSED - i * h
        force = relaxed_let_go_force(a, u)
        if force is None:
            break
        least = min(least, force)
        load = 2 * math.pi * a * WORK * GLASSY - MODULUS * MODULUS * u * u
        if 2 * a / RADIUS <= math.pi * WORK * GLASSY / math.sqrt(load) / MODULUS:
            break  # dD/da <= 0: the peel cascades from here
    return least


def shear_break(speed):
    """u_b: the shear [m] at which the glue's edge lets go during a shear at the speed, from rest.

    The edge (relaxed, q_z = E_inf (d_held - d_max), the eased press's tension) carries
    q_x = G_inf u + G_1 V tau (1 - e^(-u/(V tau))) and lets go where q_x^2/G_0 + q_z^2/E_0 =
    2 pi a_g dgamma; q_x grows with u, so bisection.
    """
    edge_load = MODULUS * (HELD_DEPTH - PRESS_DEPTH)
    limit = math.sqrt(GLASSY * (2 * math.pi * GLUED_RADIUS_PRESSED * WORK -
                                edge_load**2 / GLASSY))
    lag = speed * TAU

    def load(u):
        return MODULUS * u + ARM_MODULUS * lag * -math.expm1(-u / lag)

    low, high = 0.0, limit / MODULUS
    for _ in range(200):
        mid = 0.5 * (low + high)
        low, high = (mid, high) if load(mid) < limit else (low, mid)
    return 0.5 * (low + high)


def check_against_closed_forms(table, statuses, springs):
    """Prints every comparison with the closed forms; returns the number that miss."""
    # The table holds pull-offs as positive tensions; the closed forms give forces (< 0 pulls).
    unsheared = -relaxed_let_go_force(GLUED_RADIUS_PRESSED, 0.0)
    tolerance = unsheared / springs
    misses = 0
    print(f"closed forms (a_g = {GLUED_RADIUS_PRESSED:.6e} m, {springs} springs, "
          f"tolerance 1/N of the unsheared pull-off = {tolerance:.2e} N)")
    print(f"  unsheared pull-off -F(a_g) = sqrt(8 pi a_g^3 dgamma E_0) - 4 E_inf a_g^3/(3R) "
          f"= {unsheared:.6e} N")
    for (speed, hold, rebinding), curve in sorted(table.items()):
        error = curve[0.0] - unsheared
        misses += abs(error) > tolerance
        print(f"    {speed_label(speed):>14} {hold:6g} {rebinding:>6}: {curve[0.0]:.6e} N, "
              f"off {error:+.2e} N{'  MISS' if abs(error) > tolerance else ''}")
    print("  after a hold of 10 tau: pull-off [N] against the relaxed peel's least force "
          "(u/u_c: sweep, closed form, difference)")
    for (speed, hold, rebinding), curve in sorted(table.items()):
        if hold != RELAXED_HOLD:
            continue
        limit = shear_break(speed)
        for u in sorted(curve):
            if u >= limit:
                continue
            expected = 0.0 - relaxed_pull_off(u)
            error = curve[u] - expected
            miss = abs(error) > tolerance
            misses += miss
            print(f"    {speed_label(speed):>14} {rebinding:>6} {u / U_C:5.2f}: {curve[u]:.6e} "
                  f"{expected:.6e} {error:+.2e}{'  MISS' if miss else ''}")
    low, high = 0.0, math.sqrt(2 * math.pi * GLUED_RADIUS_PRESSED * WORK * GLASSY) / MODULUS
    for _ in range(60):
        mid = 0.5 * (low + high)
        low, high = (mid, high) if relaxed_pull_off(mid, 2000) < 0.0 else (low, mid)
    print(f"  (relaxed, the pull-off reaches 0 at u = {low / U_C:.3f} u_c, below u_b: the glue "
          "survives such a shear but the contact no longer pulls)")
    print("  without rebinding, the glue breaks during the shear above u_b "
          "(status shear-off exactly there; sqrt(E_0/E_inf) = "
          f"{math.sqrt(GLASSY / MODULUS):.4f})")
    for speed in sorted({key[0] for key in statuses}):
        limit = shear_break(speed)
        rows = [(key[1], u, status, table[key][u]) for key, runs in statuses.items()
                if key[0] == speed and key[2] == "false" for u, status in runs.items()]
        # Above u_b the glue is gone before the pull: a pressed contact under friction carries
        # no tension, so the pull-off is 0 there too.
        wrong = [row for row in rows
                 if (row[2] == "shear-off") != (row[1] > limit) or (row[1] > limit and row[3])]
        broken = sorted({u for hold, u, status, force in rows if status == "shear-off"})
        first = f"{broken[0] / U_C:.2f}" if broken else "none"
        misses += len(wrong)
        print(f"    {speed_label(speed):>14}: u_b = {limit / U_C:.4f} u_c; first shear-off "
              f"(and no pull from there on) in the sweep at {first} u_c"
              f"{'  MISS ' + str(len(wrong)) if wrong else ''}")
    return misses


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--results", required=True, help="folder of the sweeps' CSVs")
    args = parser.parse_args()
    rows = read_rows(os.path.join(args.results, "pull_off_after_shear_relaxing.csv"),
                     (SHEAR_KEY, SPEED_KEY, HOLD_KEY, "loading.rebinding", "peak_normal_force",
                      "status", "springs"))
    table = {}
    statuses = {}
    for row in rows:
        key = (float(row[SPEED_KEY]), float(row[HOLD_KEY]), row["loading.rebinding"])
        table.setdefault(key, {})[float(row[SHEAR_KEY])] = pull_off(row)
        statuses.setdefault(key, {})[float(row[SHEAR_KEY])] = row["status"]
    springs = {int(row["springs"]) for row in rows}
    if len(springs) != 1 or RELAXED_HOLD not in {key[1] for key in table}:
        print("plot_pull_off_after_shear_relaxing: the sweep is not at one spring count with "
              f"a hold of {RELAXED_HOLD:g} s", file=sys.stderr)
        sys.exit(2)
    shears = sorted({u for curve in table.values() for u in curve})
    failed = 0
    if any(len(curve) != len(shears) or 0.0 not in curve for curve in table.values()):
        print("plot_pull_off_after_shear_relaxing: the sweep misses rows", file=sys.stderr)
        sys.exit(2)
    print("pull-off / unsheared pull-off against u/u_c (relaxing bulk, E_0 = 10 E_inf, tau = 1 s)")
    print(f"  {'speed':>14} {'hold':>6} {'rebind':>6}  " +
          " ".join(f"{u / U_C:5.2f}" for u in shears))
    for (speed, hold, rebinding), curve in sorted(table.items()):
        reference = curve[0.0]
        ratios = [curve[u] / reference for u in shears]
        failed += sum(r > 1.01 for r in ratios)
        print(f"  {speed_label(speed):>14} {hold:6g} {rebinding:>6}  " +
              " ".join(f"{r:5.3f}" for r in ratios))
    misses = check_against_closed_forms(table, statuses, springs.pop())

    holds = sorted({key[1] for key in table})
    speeds = sorted({key[0] for key in table})
    fig, axes = plt.subplots(1, len(holds), figsize=(5.0 * len(holds), 4.2), sharey=True)
    axes = axes if len(holds) > 1 else [axes]
    elastic_path = os.path.join(args.results, "pull_off_after_shear_2000.csv")
    elastic = None
    if os.path.exists(elastic_path):
        elastic = [r for r in read_rows(elastic_path, (ELASTIC_KEY, "loading.rebinding",
                                                        "peak_normal_force"))
                   if r["loading.rebinding"] == "false"]
    colors = ["tab:blue", "tab:orange", "tab:red"]
    for ax, hold in zip(axes, holds):
        if elastic:
            reference = pull_off(elastic[0])
            ax.plot([float(r[ELASTIC_KEY]) / U_C for r in elastic],
                    [pull_off(r) / reference for r in elastic], "k-", lw=1.0,
                    label="elastic (E_inf), 2000 springs")
        for color, speed in zip(colors, speeds):
            for rebinding, style in (("false", "o-"), ("true", "x--")):
                curve = table[(speed, hold, rebinding)]
                ax.plot([u / U_C for u in shears], [curve[u] / curve[0.0] for u in shears], style,
                        color=color, ms=4, mfc="none", lw=0.8,
                        label=f"shear {speed_label(speed)}, rebinding {rebinding}")
        for x, text in ((math.sqrt(10.0), "sqrt(E0/Einf) u_c"), (1.0 / math.sqrt(10.0), "")):
            ax.axvline(x, color="0.6", lw=0.8, ls="--")
            if text:
                ax.text(x + 0.03, 0.9, text, color="0.4", fontsize=7)
        ax.set_title(f"held {hold:g} s (tau = 1 s) after the shear", fontsize=9)
        ax.set_xlabel("prior shear displacement u / u_c (elastic, G_inf)")
        ax.grid(alpha=0.3)
    axes[0].set_ylabel("pull-off force / pull-off force without shear")
    axes[-1].legend(fontsize=6, loc="center right")
    fig.suptitle("pull-off after shear on a relaxing bulk (pull_off_after_shear_relaxing.toml)",
                 fontsize=9)
    fig.tight_layout()
    for ext in ("png", "svg"):
        fig.savefig(os.path.join(args.results, f"pull_off_after_shear_relaxing.{ext}"), dpi=130)
    plt.close(fig)
    print(f"drew {os.path.join(args.results, 'pull_off_after_shear_relaxing.png')}")
    if failed:
        print(f"plot_pull_off_after_shear_relaxing: {failed} pull-off(s) above the unsheared one",
              file=sys.stderr)
    if misses:
        print(f"plot_pull_off_after_shear_relaxing: {misses} comparison(s) off their closed form",
              file=sys.stderr)
    if failed or misses:
        sys.exit(1)


if __name__ == "__main__":
    main()
