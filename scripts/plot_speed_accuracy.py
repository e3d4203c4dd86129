#!/usr/bin/env python3
"""Speed against accuracy: relative error of the critical force against wall time, per method.

Reads the CSV written by bench/'s mdrsim_accuracy driver and draws one panel per case and
normal control: a line per method (and per stepping increment), the Pareto front of all
points dashed, and each method's observed order (slope of log error against log springs)
in the legend. The continuum route (no springs) is one line over its rtol values (its
error does not follow rtol: each root search converges to rounding); the Pareto front is
the spring rows'. Writes speed_accuracy.png and .svg. Run with Debian's /usr/bin/python3.
"""
import argparse
import csv
import math
import os
import sys
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

STYLE = {
    "event": ("tab:blue", "o"),
    "event+richardson": ("tab:green", "s"),
    "stepping": ("tab:red", "^"),
    "continuum": ("tab:purple", "D"),
}


def read_rows(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    for r in rows:
        r["springs"] = int(r["springs"])
        r["relative_error"] = max(float(r["relative_error"]), 1e-16)
        r["time_s"] = float(r["time_s"])
        r["rtol"] = float(r["rtol"]) if r.get("rtol") else None
    return rows


def observed_order(points):
    """Least-squares slope of -log(error) against log(springs)."""
    if len(points) < 2:
        return float("nan")
    xs = [math.log(p["springs"]) for p in points]
    ys = [-math.log(p["relative_error"]) for p in points]
    mx, my = sum(xs) / len(xs), sum(ys) / len(ys)
    sxx = sum((x - mx) ** 2 for x in xs)
    return sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sxx if sxx else float("nan")


def pareto_front(points):
    """Points that no other point beats in both time and error, by increasing time."""
    front, best = [], float("inf")
    for p in sorted(points, key=lambda p: (p["time_s"], p["relative_error"])):
        if p["relative_error"] < best:
            front.append(p)
            best = p["relative_error"]
    return front


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--csv", required=True, help="speed_accuracy.csv from mdrsim_accuracy")
    parser.add_argument("--out", required=True, help="folder for speed_accuracy.png/.svg")
    args = parser.parse_args()
    rows = read_rows(args.csv)
    panels = sorted({(r["case"], r["control"]) for r in rows})
    if not panels:
        sys.exit(f"{args.csv}: no rows")
    cols = 2
    fig, axes = plt.subplots((len(panels) + cols - 1) // cols, cols, figsize=(12, 9), squeeze=False)
    for ax, (case, control) in zip(axes.flat, panels):
        here = [r for r in rows if r["case"] == case and r["control"] == control]
        lines = defaultdict(list)
        for r in here:
            label = r["method"] if r["method"] != "stepping" else f"stepping, increment {r['increment']}"
            lines[(r["method"], label)].append(r)
        for (method, label), points in sorted(lines.items()):
            colour, marker = STYLE.get(method, ("black", "x"))
            if method == "continuum":  # no springs, no order: a point per rtol
                points.sort(key=lambda p: -p["rtol"])
                rtols = f"{points[0]['rtol']:.0e}..{points[-1]['rtol']:.0e}"
                ax.loglog([p["time_s"] for p in points], [p["relative_error"] for p in points],
                          marker=marker, color=colour, linestyle="none",
                          label=f"continuum route, no springs (rtol {rtols})")
                continue
            points.sort(key=lambda p: p["springs"])
            alpha = 1.0 if method != "stepping" else 0.35 + 0.65 * (1 - math.log10(float(points[0]["increment"])) / -4)
            order = observed_order(points)
            ax.loglog([p["time_s"] for p in points], [p["relative_error"] for p in points],
                      marker=marker, color=colour, alpha=min(1.0, max(0.3, alpha)),
                      label=f"{label} (order {order:.1f})")
        front = pareto_front([r for r in here if r["method"] != "continuum"])
        ax.loglog([p["time_s"] for p in front], [p["relative_error"] for p in front], "k--",
                  linewidth=1, label="Pareto front of the spring rows")
        ax.set_title(f"{case}, {control} normal control")
        ax.set_xlabel("wall time per run [s]")
        ax.set_ylabel("relative error of the critical force (floor 1e-16)")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=7)
    for ax in list(axes.flat)[len(panels):]:
        ax.set_visible(False)
    fig.suptitle("mdrsim: speed against accuracy (orders: slope of error against springs)")
    fig.tight_layout()
    os.makedirs(args.out, exist_ok=True)
    for ext in ("png", "svg"):
        fig.savefig(os.path.join(args.out, f"speed_accuracy.{ext}"), dpi=130)
    print(f"plot: wrote {os.path.join(args.out, 'speed_accuracy')}.png and .svg")


if __name__ == "__main__":
    main()
