#!/usr/bin/python3
"""Draws a loading program's force-displacement loops from `mdrsim run --trajectory`.

Run with Debian's Python, which has matplotlib:
    /usr/bin/python3 scripts/plot_program.py TRAJECTORY.csv [--json RESULT.json] [--out NAME] [--title TEXT]

The normal force against the indentation and, where the program moves the tangential axis,
the tangential force against the tangential displacement; one colour per stage, so that a cycle's hysteresis (the area the loop
encloses is the energy it dissipated) and its jumps are seen at a glance. Jumps are drawn as
dashed lines: the state moves there without passing through equilibria.
The axes are in the SI unit with the prefix that suits their range (um and mN for a
centimetre sphere), never with an offset. The title is --title, else the scene's title from the
run's --json (`mdrsim run --json`), else the trajectory's file name.
Writes NAME.png and NAME.svg (default: next to the CSV, with its stem).
"""

import argparse
import csv
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

def read_rows(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    if rows and "stage" not in rows[0]:
        sys.exit(f"plot_program: {path} has no 'stage' column: is it an mdrsim trajectory?")
    return rows


def stage_segments(rows):
    """The path per stage in order: (name, [(d, F, ux, Fx, is_jump, after_jump)]). Rows inside a cascade
    (in_cascade = 1) are not equilibria and are left out; a `jump` row is the state after the
    cascade, reached from the point before it without passing through equilibria."""
    stages = []
    previous = None
    for r in rows:
        if r["in_cascade"] == "1" or r["event"] in ("instability", "finished"):
            continue
        state = (float(r["indentation"]), float(r["normal_force"]),
                 float(r["tangential_displacement"]), float(r["tangential_force"]))
        # p[5]: the state a jump left, also as the stage end that repeats it (not an
        # equilibrium the loading passed through: left out of the axis limits).
        jumped = r["event"] == "jump" or (previous is not None and previous[5]
                                          and previous[:4] == state)
        point = state + (r["event"] == "jump", jumped)
        previous = point
        if not stages or stages[-1][0] != r["stage"]:
            stages.append((r["stage"], []))
        stages[-1][1].append(point)
    return stages


def equilibrium_limits(stages, i):
    """The range of coordinate i over the equilibria (not the states after jumps), with a
    margin: a jump off the contact under fixed load ends wherever the runaway stopped
    (millimetres away, or anywhere), which would squash every loop into a vertical line."""
    values = [p[i] for _, points in stages for p in points if not p[5]]
    if not values:
        return None
    lo, hi = min(values), max(values)
    pad = 0.05 * (hi - lo) if hi > lo else (abs(hi) * 0.05 or 1e-12)
    return lo - pad, hi + pad


# SI prefixes, largest first: an axis takes the largest that leaves its largest value >= 1.
PREFIXES = ((1.0, ""), (1e-3, "m"), (1e-6, "\u00b5"), (1e-9, "n"), (1e-12, "p"))


def unit_of(limits):
    """(factor, prefix) for an axis spanning `limits` [SI]: the values shown are SI / factor."""
    largest = max(abs(limits[0]), abs(limits[1])) if limits else 0.0
    for factor, prefix in PREFIXES:
        if largest >= factor:
            return factor, prefix
    return PREFIXES[0] if largest == 0.0 else PREFIXES[-1]


def draw(ax, stages, xi, yi, xlabel, ylabel):
    """Draws coordinate yi against xi of every stage; xlabel and ylabel name them with "{}"
    where the unit goes (its prefix and the SI unit, e.g. "indentation d [{}m]")."""
    colours = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    xlimits, ylimits = equilibrium_limits(stages, xi), equilibrium_limits(stages, yi)
    (xf, xp), (yf, yp) = unit_of(xlimits), unit_of(ylimits)

    def scaled(point):
        q = list(point)
        q[xi] /= xf
        q[yi] /= yf
        return tuple(q)

    stages = [(name, [scaled(p) for p in points]) for name, points in stages]
    last = None
    for n, (name, points) in enumerate(stages):
        colour = colours[n % len(colours)]
        xs, ys = ([last[xi]], [last[yi]]) if last is not None else ([], [])
        labelled = False
        for p in points:
            if p[4] and xs:
                # A jump: the solid path so far, then a dashed line to the state after it.
                ax.plot(xs, ys, color=colour, lw=1.4, label=None if labelled else name)
                labelled = labelled or len(xs) > 1
                ax.plot([xs[-1], p[xi]], [ys[-1], p[yi]], color=colour, lw=1.0, ls="--")
                xs, ys = [], []
            xs.append(p[xi])
            ys.append(p[yi])
        if xs:
            ax.plot(xs, ys, color=colour, lw=1.4, label=None if labelled else name)
        if points:
            last = points[-1]
    # Zero stays in view (the force axis crosses it); jumps that leave the frame are clipped.
    for limits, factor, setter in ((xlimits, xf, ax.set_xlim), (ylimits, yf, ax.set_ylim)):
        if limits is not None:
            setter(min(limits[0] / factor, 0.0), max(limits[1] / factor, 0.0))
    # Readable numbers at any range: no "1e-6" and "+2.7e1" above the axis.
    ax.ticklabel_format(useOffset=False, style="plain")
    ax.set_xlabel(xlabel.format(xp))
    ax.set_ylabel(ylabel.format(yp))
    ax.axhline(0.0, color="grey", lw=0.5)
    ax.grid(alpha=0.3)
    handles, labels = ax.get_legend_handles_labels()
    unique = dict(zip(labels, handles))
    ax.legend(unique.values(), unique.keys(), fontsize=8)


def title_of(args):
    """--title, else the scene's title in the run's JSON, else the trajectory's file name: never
    a path, which says where the file lay on one machine and nothing of the run."""
    if args.title:
        return args.title
    if args.json:
        with open(args.json) as f:
            title = json.load(f).get("scene", {}).get("title")
        if title:
            return title
    return os.path.basename(args.trajectory)


def figure(trajectory, title):
    """The figure of the trajectory CSV at `trajectory`, titled `title`."""
    rows = read_rows(trajectory)
    if not rows:
        sys.exit(f"plot_program: {trajectory} has no rows")
    stages = stage_segments(rows)
    # The tangential panel only where the program moves that axis.
    sheared = any(p[2] != 0.0 or p[3] != 0.0 for _, points in stages for p in points)
    # Constrained layout keeps the right panel's axis label clear of the left panel.
    fig, axes = plt.subplots(1, 2 if sheared else 1, figsize=(12 if sheared else 6, 4.6),
                             squeeze=False, constrained_layout=True)
    draw(axes[0][0], stages, 0, 1, "indentation d [{}m]", "normal force F [{}N]")
    if sheared:
        draw(axes[0][1], stages, 2, 3, "tangential displacement u_x [{}m]",
             "tangential force F_x [{}N]")
    fig.suptitle(title)
    return fig


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("trajectory")
    parser.add_argument("--out", help="output path without extension")
    parser.add_argument("--json", help="the run's JSON (mdrsim run --json): its scene's title")
    parser.add_argument("--title", default=None)
    args = parser.parse_args()
    fig = figure(args.trajectory, title_of(args))
    out = args.out or os.path.splitext(args.trajectory)[0]
    for ext in ("png", "svg"):
        fig.savefig(f"{out}.{ext}", dpi=150 if ext == "png" else None, bbox_inches="tight")
    print(f"plot_program: wrote {out}.png and .svg")


if __name__ == "__main__":
    main()
