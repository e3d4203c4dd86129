"""Graded media: the parabola's pull-off against the grading exponent k under both controls
beside the closed forms -(3 + k) pi dgamma R / 2 (fixed load) and -(1 - k)(5 + 3k) pi dgamma R /
(2 (3 + k)) (fixed grips), on the continuum route and on the graded spring row; prints the table
and exits 1 where a continuum number is beyond 1e-6 of its closed form or a row's beyond its own
error estimate.

Reads the sweeps the main job writes into RESULTS: graded_{control}.csv (the continuum route,
rtol 1e-10) and graded_row_{control}.csv (the spring row, rtol 1e-6), each a sweep of
material.grading.exponent over scenes/graded/graded_parabola.toml, whose R and dgamma it reads.
"""

import argparse
import csv
import math
import os
import sys
import tomllib

# The tolerance on the continuum route, which runs at rtol 1e-10.
TOLERANCE = 1e-6
CONTROLS = ("fixed_load", "fixed_grips")


def read_rows(path):
    with open(path, newline="") as handle:
        return list(csv.DictReader(row for row in handle if not row.startswith("#")))


def closed_form(k, control):
    """F / (pi dgamma R) of the parabola's pull-off on the graded half-space (docs/graded.md)."""
    if control == "fixed_load":
        return -(3.0 + k) / 2.0
    return -(1.0 - k) * (5.0 + 3.0 * k) / (2.0 * (3.0 + k))


def table(results, scene):
    """(k, control, P continuum, P closed form, relative difference, P row or None,
    row's |error| / its estimate or None), P = F / (pi dgamma R)."""
    with open(scene, "rb") as handle:
        parsed = tomllib.load(handle)
    scale = math.pi * parsed["material"]["work_of_adhesion"] * parsed["profile"]["radius"]
    out = []
    for control in CONTROLS:
        on_row = {}
        row_path = os.path.join(results, f"graded_row_{control}.csv")
        if os.path.exists(row_path):
            for row in read_rows(row_path):
                k = float(row["material.grading.exponent"])
                force = float(row["normal_force"])
                estimate = float(row["critical_error_estimate"])
                error = abs(force - closed_form(k, control) * scale)
                on_row[k] = (force / scale, error / estimate if estimate > 0 else math.inf)
        for row in read_rows(os.path.join(results, f"graded_{control}.csv")):
            k = float(row["material.grading.exponent"])
            engine = float(row["normal_force"]) / scale
            reference = closed_form(k, control)
            row_p, row_ratio = on_row.get(k, (None, None))
            out.append((k, control, engine, reference, abs(engine - reference) / abs(reference),
                        row_p, row_ratio))
    return out


def draw(rows, out):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(figsize=(6.4, 4.6))
    ks = [0.9 * j / 180 for j in range(181)]
    for control, style in zip(CONTROLS, ("k-", "k--")):
        axes.plot(ks, [closed_form(k, control) for k in ks], style, lw=1,
                  label=f"closed form, {control.replace('_', ' ')}")
    for control, marker in zip(CONTROLS, ("o", "s")):
        pts = [(k, p) for k, c, p, _, _, _, _ in rows if c == control]
        axes.plot(*zip(*pts), marker, mfc="none", ms=8,
                  label=f"mdrsim continuum, {control.replace('_', ' ')}")
        row_pts = [(k, r) for k, c, _, _, _, r, _ in rows if c == control and r is not None]
        if row_pts:
            axes.plot(*zip(*row_pts), marker, ms=3, color="k",
                      label=f"mdrsim spring row, {control.replace('_', ' ')}")
    axes.set_xlabel("grading exponent k   (E(z) = E0 (z / z0)^k)")
    axes.set_ylabel("F / (pi dgamma R)")
    axes.set_title("Parabola on a graded half-space: pull-off against k")
    axes.legend(fontsize=7)
    fig.tight_layout()
    for ext in ("png", "svg"):
        fig.savefig(os.path.join(out, f"graded_pull_off.{ext}"))
    print(f"wrote {os.path.join(out, 'graded_pull_off.png')}")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--results", default="results")
    parser.add_argument("--scene", default="scenes/graded/graded_parabola.toml")
    args = parser.parse_args()
    rows = table(args.results, args.scene)
    print("Graded media, parabola: P = F/(pi dgamma R) against the closed forms")
    print(f"{'k':>5} {'control':>11} {'continuum':>14} {'closed form':>14} {'rel. diff':>10}"
          f" {'spring row':>14} {'err/est':>8}")
    failed = []
    for k, control, engine, reference, diff, row, ratio in rows:
        if not diff <= TOLERANCE:
            failed.append(f"continuum k = {k} {control}: {diff:.2e} > {TOLERANCE}")
        row_text = ""
        if row is not None:
            row_text = f" {row:14.9f} {ratio:8.3f}"
            if not ratio <= 1.0:
                failed.append(f"row k = {k} {control}: beyond its estimate ({ratio:.2f}x)")
        print(f"{k:5.3g} {control:>11} {engine:14.9f} {reference:14.9f} {diff:10.2e}{row_text}")
    draw(rows, args.results)
    for line in failed:
        print(f"FAIL {line}")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
