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
hold and rebinding) and checks only that the sweep is complete and that nothing shows a
pull-off above the unsheared one by more than 1e-2 (exit 1), or input that is not such a sweep
(exit 2). Draws DIR/pull_off_after_shear_relaxing.png and .svg.
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
WORK = 0.05  # dgamma [J/m^2]
GLUED_RADIUS = 5.209397078678047e-4  # a_g = 2 a0 of the relaxed material [m]
U_C = math.sqrt(2 * math.pi * GLUED_RADIUS * WORK / MODULUS)  # [m]
TAU = 1.0  # [s]
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


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--results", required=True, help="folder of the sweeps' CSVs")
    args = parser.parse_args()
    rows = read_rows(os.path.join(args.results, "pull_off_after_shear_relaxing.csv"),
                     (SHEAR_KEY, SPEED_KEY, HOLD_KEY, "loading.rebinding", "peak_normal_force"))
    table = {}
    for row in rows:
        key = (float(row[SPEED_KEY]), float(row[HOLD_KEY]), row["loading.rebinding"])
        table.setdefault(key, {})[float(row[SHEAR_KEY])] = pull_off(row)
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
        sys.exit(1)


if __name__ == "__main__":
    main()
