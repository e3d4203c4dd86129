#!/usr/bin/python3
"""Draws the pull-off force after a prior shear against the paper's path, with and without rebinding.

Run with Debian's Python, which has matplotlib:
    /usr/bin/python3 scripts/plot_pull_off_after_shear.py --results DIR [--springs 2000 8000]

Reads what the main job (scripts/reproduce.sh) writes:
    DIR/pull_off_after_shear_N.csv      mdrsim sweep scenes/programs/pull_off_after_shear.toml
        --vary loading.stage.2.tangential.to=0:2u_c:33 --vary loading.rebinding=false,true
        --set discretization.springs=N
    DIR/pull_off_after_shear_continuum.csv   mdrsim sweep scenes/fig3a_fixed_grips.toml
        --vary loading.tangential.displacement=0:2u_c:33 on the continuum route at rtol 1e-10
The program glues a sphere on touch at a_g = 2 a0 (edge unstretched), shears it under fixed
grips to u with d held, then pulls it off under fixed grips (u held), under Coulomb friction
mu = 1: the experiment of Oliver, Dalmas and Scheibert. Every glued spring carries the stretch
u, so until u_c = sqrt(2 pi a_g dgamma / G*) the glue holds whole, the pull-off is the paper's
path with u held (Fig. 3a's shorthand, here on the continuum route), and friction takes no part
(the springs let go in tension, out of contact). The pull-off force is the most tensile force
of the retraction (the JSON's peak_adhesion; none where the glue lets go while the contact is
still pressed): it falls with u and vanishes at a critical shear displacement below u_c.

Checks (exit 1 on a wrong number, 2 on input that is not such a sweep; never for timing):
  - without rebinding, where the paper's path has a tensile peak the program has one within
    3/N of the pull-off force without shear (the row's O(1/N), measured 1.5/N: an error of
    the force, not of the vanishing peak, whose relative error grows where it vanishes), and
    where the path has none, neither has the program;
  - with rebinding, the same as without it where the path has a tensile peak (nothing that let
    go can hold a glue again in tension), and elsewhere either no tensile force or only the last
    spring's: a spring unloaded to no stretch at x_1 = dx glues and lets go at
    2 E* dx sqrt(2 pi dx dgamma / E*) (both halves), a row's artefact that falls as N^-3/2 (to
    1e-9).
Draws DIR/pull_off_after_shear.png and .svg: F_pull-off / F_pull-off(u = 0) against u / u_c.
"""

import argparse
import csv
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

# The scene's numbers (scenes/programs/pull_off_after_shear.toml).
MODULUS = 1.0e6  # E* = G* [Pa]
WORK = 0.05  # dgamma [J/m^2]
GLUED_RADIUS = 5.209397078678047e-4  # a_g = 2 a0 [m]
U_C = math.sqrt(2 * math.pi * GLUED_RADIUS * WORK / MODULUS)  # [m]
PROGRAM_KEY = "loading.stage.2.tangential.to"
PATH_KEY = "loading.tangential.displacement"


def read_rows(path):
    """The sweep's rows as dicts (the identity comment line skipped)."""
    try:
        with open(path, newline="") as f:
            lines = [line for line in f if not line.startswith("#")]
    except OSError as e:
        print(f"plot_pull_off_after_shear: cannot read {path}: {e.strerror}", file=sys.stderr)
        sys.exit(2)
    rows = list(csv.DictReader(lines))
    if not rows or "peak_normal_force" not in rows[0]:
        print(f"plot_pull_off_after_shear: {path} is not a sweep CSV", file=sys.stderr)
        sys.exit(2)
    return rows


def peak(row):
    """The most tensile force of the retraction [N], or None where nothing pulled."""
    text = row["peak_normal_force"]
    return float(text) if text else None


def lone_spring(springs):
    """The let-go force of one spring at x = dx glued unstretched, both halves [N]."""
    dx = GLUED_RADIUS / springs
    return 2 * MODULUS * dx * math.sqrt(2 * math.pi * dx * WORK / MODULUS)


def check(path_rows, rows, springs):
    """The table of one spring count; returns the number of failed checks."""
    failed = 0
    by_key = {}
    for row in rows:
        key = (float(row[PROGRAM_KEY]), row["loading.rebinding"])
        by_key[key] = row
    bound = 3.0 / springs
    scale = abs(peak(path_rows[0]))  # the pull-off force without shear
    print(f"N = {springs}: pull-off force [N] against the paper's path (continuum, rtol 1e-10)")
    print(f"  {'u/u_c':>6} {'path':>13} {'program':>13} {'err/F(0)':>10} {'rebinding':>13}  ok")
    for path_row in path_rows:
        u = float(path_row[PATH_KEY])
        expected = peak(path_row)
        without = by_key.get((u, "false"))
        with_ = by_key.get((u, "true"))
        if without is None or with_ is None:
            print(f"plot_pull_off_after_shear: no program row at u = {u}", file=sys.stderr)
            sys.exit(2)
        got, rebound = peak(without), peak(with_)
        if expected is None:
            error = None
            ok = got is None and (
                rebound is None or abs(-rebound - lone_spring(springs)) <= 1e-9 * lone_spring(springs)
            )
        else:
            error = abs(got - expected) / scale if got is not None else math.inf
            ok = error <= bound and rebound == got
        failed += not ok
        fmt = lambda v: f"{v:13.6e}" if v is not None else f"{'none':>13}"  # noqa: E731
        err = f"{error:10.2e}" if error is not None else f"{'':>10}"
        print(f"  {u / U_C:6.3f} {fmt(expected)} {fmt(got)} {err} {fmt(rebound)}  "
              f"{'ok' if ok else 'WRONG'}")
    print(f"  bounds: 3/N = {bound:.1e} of F(0); the last spring's glue "
          f"{lone_spring(springs):.4e} N (to 1e-9)")
    return failed


def draw(path_rows, by_springs, out):
    reference = -peak(path_rows[0])
    fig, ax = plt.subplots(figsize=(6.4, 4.4))
    ax.plot([float(r[PATH_KEY]) / U_C for r in path_rows],
            [-(peak(r) or 0.0) / reference for r in path_rows], "k-", lw=1.2,
            label="paper's path (continuum route)")
    markers = {0: ("o", "s"), 1: ("x", "+")}
    for index, (springs, rows) in enumerate(sorted(by_springs.items())):
        for rebinding, marker in zip(("false", "true"), markers[index % 2]):
            pick = [r for r in rows if r["loading.rebinding"] == rebinding]
            ax.plot([float(r[PROGRAM_KEY]) / U_C for r in pick],
                    [-(peak(r) or 0.0) / reference for r in pick], marker, ms=5,
                    mfc="none", label=f"program, {springs} springs, rebinding {rebinding}")
    ax.axvline(1.0, color="0.6", lw=0.8, ls="--")
    ax.text(1.02, 0.9, "u_c: the glue breaks", color="0.4", fontsize=8)
    ax.set_xlabel("prior shear displacement u / u_c")
    ax.set_ylabel("pull-off force / pull-off force without shear")
    ax.set_title("pull-off after shear (pull_off_after_shear.toml)", fontsize=9)
    ax.legend(fontsize=7, loc="center right")  # the empty region past the critical shear
    ax.grid(alpha=0.3)
    fig.tight_layout()
    for ext in ("png", "svg"):
        fig.savefig(os.path.join(out, f"pull_off_after_shear.{ext}"), dpi=130)
    plt.close(fig)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--results", required=True, help="folder of the sweeps' CSVs")
    parser.add_argument("--springs", type=int, nargs="+", default=[2000, 8000])
    args = parser.parse_args()
    path_rows = read_rows(os.path.join(args.results, "pull_off_after_shear_continuum.csv"))
    if PATH_KEY not in path_rows[0] or peak(path_rows[0]) is None:
        print("plot_pull_off_after_shear: the path's sweep has no pull-off at u = 0",
              file=sys.stderr)
        sys.exit(2)
    by_springs = {}
    failed = 0
    for springs in args.springs:
        rows = read_rows(os.path.join(args.results, f"pull_off_after_shear_{springs}.csv"))
        if PROGRAM_KEY not in rows[0]:
            print(f"plot_pull_off_after_shear: no {PROGRAM_KEY} column", file=sys.stderr)
            sys.exit(2)
        by_springs[springs] = rows
        failed += check(path_rows, rows, springs)
    draw(path_rows, by_springs, args.results)
    print(f"drew {os.path.join(args.results, 'pull_off_after_shear.png')}")
    if failed:
        print(f"plot_pull_off_after_shear: {failed} WRONG number(s)", file=sys.stderr)
        sys.exit(1)


if __name__ == "__main__":
    main()
