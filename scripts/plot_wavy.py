#!/usr/bin/python3
"""Draws a wavy sphere's pull-off force against its ripple amplitude from `mdrsim sweep`.

Run with Debian's Python, which has matplotlib:
    /usr/bin/python3 scripts/plot_wavy.py --csv SWEEP.csv [--out DIR]

The sweep varies `profile.amplitude` of scenes/wavy_sphere.toml (the main job runs it). The
critical force F/F0 (fixed load: the pull-off force) is drawn against A; the amplitudes whose
run has a state that is not one contact disk (the sweep's disk_valid column: the surface
touches the indenter again outside the contact) are shaded, their points drawn open: there
the MDR's answer does not hold. Writes DIR/wavy_pull_off.png and .svg.
"""

import argparse
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def read_sweep(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(line for line in f if not line.startswith("#")))
    need = {"profile.amplitude", "dimensionless_normal_force", "disk_valid", "status"}
    if not rows or not need <= set(rows[0]):
        sys.exit(f"plot_wavy: {path} lacks the columns {sorted(need)}: is it a sweep of "
                 "profile.amplitude with scales?")
    return [r for r in rows if r["status"] == "instability" and r["dimensionless_normal_force"]]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--csv", required=True)
    parser.add_argument("--out", default=None, help="folder of the figure (default: the CSV's)")
    args = parser.parse_args()
    rows = read_sweep(args.csv)
    amplitude = [float(r["profile.amplitude"]) * 1e9 for r in rows]  # [nm]
    force = [float(r["dimensionless_normal_force"]) for r in rows]
    valid = [r["disk_valid"] == "true" for r in rows]

    fig, ax = plt.subplots(figsize=(6.4, 4.4))
    invalid = [a for a, v in zip(amplitude, valid) if not v]
    if invalid:
        first = min(invalid)
        below = [a for a in amplitude if a < first]
        start = 0.5 * (first + max(below)) if below else first
        ax.axvspan(start, max(amplitude) + 0.02 * (max(amplitude) - min(amplitude)),
                   color="tab:red", alpha=0.12, lw=0,
                   label="not one contact disk (MDR does not hold)")
    ax.plot(amplitude, force, color="tab:blue", lw=1.2)
    ax.plot([a for a, v in zip(amplitude, valid) if v], [f for f, v in zip(force, valid) if v],
            "o", color="tab:blue", label="pull-off force, one disk")
    if invalid:
        ax.plot(invalid, [f for f, v in zip(force, valid) if not v], "o", mfc="white",
                color="tab:red", label="pull-off force, disk check failed")
    ax.axhline(-1.0, color="0.5", lw=0.8, ls="--", label="smooth sphere (JKR, $-F_0$)")
    ax.set_xlabel("ripple amplitude A [nm]  (wavelength 100 um, R = 1 cm)")
    ax.set_ylabel("critical force F / F0 (fixed load)")
    ax.set_title("Wavy sphere: pull-off against the ripple amplitude")
    ax.legend(fontsize=8, loc="lower left")
    ax.grid(alpha=0.3)
    fig.tight_layout()
    out = args.out or os.path.dirname(os.path.abspath(args.csv))
    for ext in ("png", "svg"):
        path = os.path.join(out, f"wavy_pull_off.{ext}")
        fig.savefig(path, dpi=130)
        print(f"wrote {path}")


if __name__ == "__main__":
    main()
