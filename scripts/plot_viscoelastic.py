"""Viscoelastic springs: the force against time of a parabola pressed at constant speed into a
standard linear solid and withdrawn at the same speed (scenes/viscoelastic/lee_radok_parabola.toml)
beside Lee-Radok's loading and Ting's unloading, computed here from the closed forms alone
(scipy's Dawson function; no number of the engine). Runs the scene, prints the errors, draws
RESULTS/viscoelastic_lee_radok.png and exits 1 where the force at a touch or a lift is further
than the row's stated error, 2 / N of F(t_m) (docs/viscoelastic.md), from the closed form, or
the separation time further than 1e-3 t_m.
"""

import argparse
import csv
import json
import math
import os
import subprocess
import sys
import tomllib

from scipy.optimize import brentq
from scipy.special import dawsn

SEPARATION_TOLERANCE = 1e-3  # of t_m


class Ramp:
    """The scene's standard linear solid (plane-strain moduli) and its path: d = V t up to
    t_m, then V (2 t_m - t)."""

    def __init__(self, scene):
        material = scene["material"]
        (term,) = material["relaxation"]
        self.e_inf = material["effective_modulus"]
        self.e_1 = term["modulus"]
        self.tau = term["time"]
        self.radius = scene["profile"]["radius"]
        press = scene["loading"]["stage"][0]
        self.speed = press["speed"]
        self.turn = press["normal"]["to"] / self.speed

    def psi(self, t):
        """int_0^t E(s) ds."""
        return self.e_inf * t - self.e_1 * self.tau * math.expm1(-t / self.tau)

    def loaded(self, t1, t):
        """(4 sqrt(R) / 3) V^(3/2) [E_inf t1^(3/2) + (3/2) E_1 tau^(3/2) e^(-(t - t1)/tau)
        (sqrt(x1) - D(sqrt(x1)))], x1 = t1 / tau: Lee-Radok's force at t1 = t, Ting's after."""
        z = math.sqrt(t1 / self.tau)
        arm = 1.5 * self.e_1 * self.tau**1.5 * math.exp(-(t - t1) / self.tau) * (z - dawsn(z))
        return 4.0 * math.sqrt(self.radius) / 3.0 * self.speed**1.5 * (
            self.e_inf * t1**1.5 + arm)

    def matching_time(self, t):
        """Ting's t1: t up to t_m, then psi(t - t1) = 2 psi(t - t_m); 0 once separated."""
        if t <= self.turn:
            return t
        target = 2.0 * self.psi(t - self.turn)
        if self.psi(t) <= target:
            return 0.0
        return brentq(lambda t1: self.psi(t - t1) - target, 0.0, self.turn, xtol=1e-15,
                      rtol=1e-15)

    def force(self, t):
        t1 = self.matching_time(t)
        return self.loaded(t1, t) if t1 > 0.0 else 0.0

    def separation(self):
        """psi(t_s) = 2 psi(t_s - t_m), in (t_m, 2 t_m]."""
        return brentq(lambda t: self.psi(t) - 2.0 * self.psi(t - self.turn), self.turn * (1 + 1e-12),
                      2.0 * self.turn, xtol=1e-15, rtol=1e-15)


def run_scene(mdrsim, scene, results):
    trajectory = os.path.join(results, "viscoelastic_lee_radok_trajectory.csv")
    summary = os.path.join(results, "viscoelastic_lee_radok.json")
    subprocess.run([mdrsim, "run", scene, "--trajectory", trajectory, "--json", summary,
                    "--log-level", "error"], check=True)
    with open(trajectory, newline="") as handle:
        rows = [r for r in csv.DictReader(handle) if r["event"] in ("touched", "lifted")]
    with open(summary) as handle:
        return rows, json.load(handle)


def draw(ramp, rows, separation, out):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(figsize=(6.4, 4.6))
    end = 1.05 * 2.0 * ramp.turn
    ts = [end * i / 800 for i in range(801)]
    axes.plot(ts, [1e3 * ramp.force(t) for t in ts], "k-", lw=1,
              label="Lee-Radok (t < t_m), Ting (t > t_m)")
    elastic = lambda t, e: 4.0 / 3.0 * e * math.sqrt(ramp.radius) * max(
        ramp.speed * min(t, 2.0 * ramp.turn - t), 0.0)**1.5
    axes.plot(ts, [1e3 * elastic(t, ramp.e_inf) for t in ts], "k:", lw=1,
              label="elastic, E_inf (slow limit)")
    axes.plot(ts, [1e3 * elastic(t, ramp.e_inf + ramp.e_1) for t in ts], "k-.", lw=0.8,
              label="elastic, E_0 (fast limit)")
    stride = max(1, len(rows) // 60)
    pts = rows[::stride]
    axes.plot([float(r["time"]) for r in pts], [1e3 * float(r["normal_force"]) for r in pts], "o",
              mfc="none", ms=5, label=f"mdrsim spring row (every {stride}th touch or lift)")
    axes.axvline(separation, color="0.6", lw=0.8, ls="--")
    axes.set_xlabel("time t [s]")
    axes.set_ylabel("normal force F [mN]")
    axes.set_title("Parabola into a standard linear solid: force against time")
    axes.legend(fontsize=7)
    fig.tight_layout()
    for ext in ("png", "svg"):
        fig.savefig(os.path.join(out, f"viscoelastic_lee_radok.{ext}"))
    print(f"wrote {os.path.join(out, 'viscoelastic_lee_radok.png')}")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--results", default="results")
    parser.add_argument("--mdrsim", default="build/apps/mdrsim")
    parser.add_argument("--scene", default="scenes/viscoelastic/lee_radok_parabola.toml")
    args = parser.parse_args()
    with open(args.scene, "rb") as handle:
        ramp = Ramp(tomllib.load(handle))
    os.makedirs(args.results, exist_ok=True)
    rows, summary = run_scene(args.mdrsim, args.scene, args.results)
    springs = summary["springs"]
    peak = ramp.force(ramp.turn)
    worst = max(rows, key=lambda r: abs(float(r["normal_force"]) - ramp.force(float(r["time"]))))
    force_error = abs(float(worst["normal_force"]) - ramp.force(float(worst["time"]))) / peak
    separation = ramp.separation()
    separated_at = summary["stages"][-1]["end_time"]
    separation_error = abs(separated_at - separation) / ramp.turn
    stated = 2.0 / springs
    print(f"Lee-Radok / Ting, {springs} springs: F(t_m) = {peak:.6e} N, t_s = {separation:.9f} s")
    print(f"  largest force error at a touch or lift: {force_error:.2e} of F(t_m) "
          f"(at t = {float(worst['time']):.6f} s; stated: {stated:.1e})")
    print(f"  separation at {separated_at:.9f} s: error {separation_error:.2e} of t_m "
          f"(stated: {SEPARATION_TOLERANCE:.0e})")
    for stage in summary["stages"]:
        e = stage["energy"]
        print(f"  {stage['name']:>9}: machine work {e['machine_work']:.6e} J = stored change "
              f"{e['stored_change']:.6e} + dissipated_by_bulk {e['dissipated_by_bulk']:.6e} "
              f"(residual {e['residual']:.1e})")
    draw(ramp, rows, separation, args.results)
    failed = []
    if not force_error <= stated:
        failed.append(f"force {force_error:.2e} of F(t_m) > {stated:.1e}")
    if not separation_error <= SEPARATION_TOLERANCE:
        failed.append(f"separation {separation_error:.2e} of t_m > {SEPARATION_TOLERANCE}")
    for line in failed:
        print(f"FAIL {line}")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
