#!/usr/bin/python3
"""Draws the crack-front codes' axisymmetric loop (a sinusoidal work of adhesion) against the uniform JKR loop.

Run with Debian's Python, which has matplotlib:
    /usr/bin/python3 scripts/plot_crack_front.py --results DIR [--amplitudes 0 0.1 0.2]

Reads what the main job (scripts/reproduce.sh) writes for each amplitude A of
scenes/programs/crack_front_sinusoid.toml (w(r) = w0 (1 + A sin(2 pi r / 0.1)), w0 = 1/pi,
E* = 3/4, R = 1, pressed to d = 0.05 under fixed grips and retracted until separation):
    DIR/crack_front_A.csv and .json    mdrsim run ... --trajectory (the row the scene gives)
    DIR/crack_front_A_rtol.json        mdrsim run ... --set discretization.rtol=1e-6
Prints each loop's peak tension (the most tensile force of the retraction, the JSON's
peak_adhesion) and its energy (the machine's work over the cycle, the JSON's work.normal:
what the jumps dissipate), at rtol 1e-6 with the run's estimates, and the jumps.

Checks (exit 1 on a wrong number, 2 on missing input; never for timing):
  - A = 0 is the reversible JKR loop: peak tension -(3/2) pi w0 R, loop energy
    E* a_in^5 / R^2 (2^(-8/3)/5 + 3/10) with a_in = (2 pi w0 R^2 / E*)^(1/3), each within
    1e-6 relative at rtol 1e-6 and within 3/N on the trajectory's row of N springs;
  - every amplitude: the rtol run says rtol is met, and the row of N springs lies within 3/N of
    it (the row's O(1/N)). The rtol values for A = 0.1 and 0.2 are held to an independent front
    tracker in tests/engine/program/radial_loop_test.cpp (within 1e-6, measured 4e-11..2e-8).
Draws DIR/crack_front.png and .svg: F against d for each amplitude, jumps dashed.
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

E_STAR, RADIUS, W0 = 0.75, 1.0, 1.0 / math.pi


def tag(amplitude):
    return f"{amplitude:g}"


def load(path):
    if not os.path.exists(path):
        print(f"plot_crack_front: {path} is missing (run scripts/reproduce.sh)", file=sys.stderr)
        sys.exit(2)
    with open(path) as f:
        return json.load(f)


def loop_points(path):
    """The equilibria in order, and the jumps as (d, F before, F after)."""
    points, jumps, previous = [], [], None
    with open(path, newline="") as f:
        for r in csv.DictReader(f):
            if r["in_cascade"] == "1" or r["event"] in ("instability", "finished"):
                continue
            state = (float(r["indentation"]), float(r["normal_force"]))
            if r["event"] == "jump" and previous is not None:
                jumps.append((state[0], previous[1], state[1]))
            points.append(state)
            previous = state
    return points, jumps


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--results", required=True)
    parser.add_argument("--amplitudes", type=float, nargs="+", default=[0.0, 0.1, 0.2])
    args = parser.parse_args()

    a_in = (2 * math.pi * W0 * RADIUS**2 / E_STAR) ** (1 / 3)
    closed = {"peak": -1.5 * math.pi * W0 * RADIUS,
              "energy": E_STAR * a_in**5 / RADIUS**2 * (2 ** (-8 / 3) / 5 + 3 / 10)}
    failed = 0
    print("crack-front test case, w(r) = w0 (1 + A sin(2 pi r / 0.1)): the loop at rtol 1e-6 "
          "(engine estimates) and on a row of N springs")
    print(f"{'A':>5} {'peak tension':>16} {'estimate':>9} {'loop energy':>15} {'estimate':>9} "
          f"{'jumps in/out':>12} {'N':>6} {'row/rtol-1':>22}  ok")
    fig, ax = plt.subplots(figsize=(7.5, 5.0))
    colours = ["black", "tab:blue", "tab:red", "tab:green", "tab:purple"]
    for i, amplitude in enumerate(args.amplitudes):
        base = os.path.join(args.results, f"crack_front_{tag(amplitude)}")
        fine = load(base + "_rtol.json")
        row = load(base + ".json")
        peak = fine["peak_adhesion"]["normal_force"]
        energy = fine["work"]["normal"]
        n = row["springs"]
        row_peak = row["peak_adhesion"]["normal_force"] / peak - 1
        row_energy = row["work"]["normal"] / energy - 1
        ok = fine["accuracy"].get("rtol_met", False) and max(abs(row_peak),
                                                           abs(row_energy)) <= 3 / n
        if amplitude == 0.0:
            ok = ok and abs(peak / closed["peak"] - 1) <= 1e-6 and \
                abs(energy / closed["energy"] - 1) <= 1e-6
        failed += 0 if ok else 1
        jumps_in = sum(1 for j in fine["jumps"] if j["kind"] == "in")
        jumps_out = len(fine["jumps"]) - jumps_in
        print(f"{amplitude:5.2f} {peak:16.10f} {fine['accuracy']['peak_error_estimate']:9.1e} "
              f"{energy:15.10f} {fine['accuracy']['work_error_estimate']['normal']:9.1e} "
              f"{jumps_in:>5}/{jumps_out:<6} {n:>6} {row_peak:11.1e}{row_energy:11.1e}  "
              f"{'ok' if ok else 'WRONG'}")
        points, jumps = loop_points(base + ".csv")
        colour = colours[i % len(colours)]
        label = "uniform (JKR)" if amplitude == 0.0 else f"A = {amplitude:g}"
        ax.plot([p[0] for p in points], [p[1] for p in points], color=colour, lw=1.0,
                label=f"{label}: peak {peak:.4f}, loop energy {energy:.4f}")
        for d, before, after in jumps:
            ax.plot([d, d], [before, after], color=colour, lw=0.8, ls="--")
    print(f"  A = 0 against the JKR loop: peak {closed['peak']:.10f}, loop energy "
          f"{closed['energy']:.10f} (to 1e-6; the rows to 3/N)")
    ax.axhline(0.0, color="grey", lw=0.5)
    ax.set_xlabel("indentation d (units: R = 1, E* = 3/4, w0 = 1/pi)")
    ax.set_ylabel("normal force F")
    ax.set_title("Approach-retract under fixed grips, w(r) = w0 (1 + A sin(2 pi r / 0.1))",
                 fontsize=10)
    ax.legend(fontsize=8, loc="center")
    fig.tight_layout()
    for ext in ("png", "svg"):
        fig.savefig(os.path.join(args.results, f"crack_front.{ext}"), dpi=150)
    print(f"  drew {os.path.join(args.results, 'crack_front.png')}")
    if failed:
        print(f"plot_crack_front: {failed} WRONG number(s)", file=sys.stderr)
        sys.exit(1)


if __name__ == "__main__":
    main()
