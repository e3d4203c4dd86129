#!/usr/bin/python3
"""Draws the paper's Figs. 2a, 2b, 3a, 3b (and a master-curve check of eq. 34) from mdrsim output.

Run with Debian's Python, which has numpy and matplotlib:
    /usr/bin/python3 scripts/plot_paper_figures.py [--results results]

Reads (written by scripts/reproduce.sh into the results directory), each run with its JSON:
    fig2_fixed_grips.csv/.json, fig2_fixed_load.csv/.json   `mdrsim run --trajectory --json`
    fig3a_fixed_grips.csv/.json, fig3a_fixed_load.csv/.json `mdrsim sweep` over u, and
                                                            `mdrsim run --json` of its scene
    fig3a_fixed_grips_nu03.csv/.json                        the same at nu = 0.3 (optional)
Writes PNG and SVG next to them:
    fig2a_fixed_grips, fig2b_fixed_load, fig3a, fig3b, fig_master_curve
Every figure draws the run it is given: its scales (F0, a0, d0) and moduli (E*, G*) come from
the run's own JSON (`scales`, `material`, the resolved `scene`), never from a scene file, so a
run with --set values is drawn with them. Lines are the paper's closed forms
(scripts/paper_reference.py, independent of the engine) where the run's profile has them (a
parabola; a sphere, whose cap is nearly one, with a note); elsewhere the simulation alone is
drawn and a note says why. Markers are the simulation. Prints one line per figure written or
left out.
"""

import argparse
import csv
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import paper_reference as ref  # noqa: E402

MARKERS_FIG2 = 200    # simulated points drawn per Fig. 2 panel
# The profiles the paper's closed forms describe: exactly, and nearly (the cap r^2/(2R) + ...).
EXACT, NEAR = "parabolic", "sphere"

RED, BLUE, BLACK, GREY = "#c0392b", "#1f4e9c", "black", "#7f7f7f"


def read_csv(path):
    # A sweep CSV starts with its identity line "# mdrsim sweep: ..." (docs/sweeps.md).
    with open(path, newline="") as f:
        return list(csv.DictReader(line for line in f if not line.startswith("#")))


class Run:
    """What a figure needs of a run, from its JSON (`mdrsim run --json`, docs/outputs.md)."""

    def __init__(self, path):
        with open(path) as f:
            result = json.load(f)
        self.path = path
        scene = result.get("scene", {})
        self.title = scene.get("title", "")
        self.profile = scene.get("profile", {}).get("type", "?")
        material = result.get("material", {})
        self.effective_modulus = material.get("effective_modulus")
        self.effective_shear_modulus = material.get("effective_shear_modulus")
        scales = result.get("scales")
        # (F0, a0, d0) [N, m, m]; None where the profile has no closed-form scales.
        self.scales = (scales["force"], scales["radius"], scales["depth"]) if scales else None

    @property
    def gamma(self):
        """G*/E* (paper eq. 9)."""
        return self.effective_shear_modulus / self.effective_modulus

    def closed_forms(self):
        """(drawn, note): whether the paper's lines apply to this run, and what to say."""
        name = os.path.basename(self.path)
        if self.scales is None:
            return False, f"{name}: profile '{self.profile}' has no scales F0, d0: SI units, no closed forms"
        if self.profile == EXACT:
            return True, None
        if self.profile == NEAR:
            return True, (f"{name}: a sphere; the lines are the paraboloid's closed forms, which its "
                          "cap approaches where a << R")
        return False, f"{name}: the paper's closed forms are a parabola's, not the {self.profile}'s: left out"


def note(text):
    print(f"plot: {text}")


def save(fig, results, name):
    for ext in ("png", "svg"):
        path = os.path.join(results, f"{name}.{ext}")
        fig.savefig(path, dpi=150 if ext == "png" else None, bbox_inches="tight")
    plt.close(fig)
    print(f"plot: wrote {os.path.join(results, name)}.png and .svg")


# --------------------------------------------------------------------------- Fig. 2

def trajectory_points(rows, f0, d0):
    """Equilibrium states of a trajectory in units of (d0, F0), subsampled to about MARKERS_FIG2.

    Keeps the preload, the stable detachments (event == detached, in_cascade == 0) and the
    instability; the cascade after the instability is not a sequence of equilibria.
    """
    kept = [r for r in rows if r["event"] in ("preload", "instability")
            or (r["event"] == "detached" and r["in_cascade"] == "0")]
    preload = [r for r in kept if r["event"] == "preload"]
    instab = [r for r in kept if r["event"] == "instability"]
    path = [r for r in kept if r["event"] == "detached"]
    conv = lambda rs: (np.array([float(r["indentation"]) / d0 for r in rs]),
                       np.array([float(r["normal_force"]) / f0 for r in rs]))
    d, f = conv(path)
    if len(d) > MARKERS_FIG2 and np.ptp(d) > 0 and np.ptp(f) > 0:
        # evenly spaced along the curve as drawn (detachments are evenly spaced in a, which
        # crowds the markers where the curve turns)
        s = np.concatenate([[0.0], np.cumsum(np.hypot(np.diff(d) / np.ptp(d), np.diff(f) / np.ptp(f)))])
        idx = np.unique(np.searchsorted(s, np.linspace(0.0, s[-1], MARKERS_FIG2)).clip(0, len(d) - 1))
        d, f = d[idx], f[idx]
    return conv(preload), (d, f), conv(instab)


def figure_fig2(results, control, panel):
    """Fig. 2a (fixed grips) or 2b (fixed load) of the run fig2_CONTROL.csv/.json."""
    rows = read_csv(os.path.join(results, f"fig2_{control}.csv"))
    run = Run(os.path.join(results, f"fig2_{control}.json"))
    analytic, why = run.closed_forms()
    if why:
        note(why)
    f0, a0, d0 = run.scales or (1.0, 1.0, 1.0)
    (pd, pf), (sd, sf), (idd, iff) = trajectory_points(rows, f0, d0)
    crit = ref.JKR_PULL_OFF_FIXED_GRIPS if control == "fixed_grips" else ref.JKR_PULL_OFF_FIXED_LOAD
    label = "fixed grips" if control == "fixed_grips" else "fixed load"

    fig, ax = plt.subplots(figsize=(6.0, 4.5))
    ax.axhline(0.0, color=GREY, lw=0.6)
    ax.axvline(0.0, color=GREY, lw=0.6)
    xs, ys = list(sd), list(sf)
    if analytic:
        a_max = max(2.0, float(rows[0]["contact_radius"]) / a0) if rows else 2.0
        a = np.linspace(0.0, a_max, 2000)
        ax.plot(3 * a ** 2 - 4 * np.sqrt(a), a ** 3 - 2 * a ** 1.5, color=BLACK, lw=1.4,
                label="analytic, eqs. (18)-(19)" + (" of the paraboloid" if run.profile == NEAR else ""))
        ax.axhline(crit, color=BLUE, lw=0.8, ls="--")
        ac = ref.critical_radius_fixed_grips(0.0)
        xs.append(3 * ac ** 2 - 4 * np.sqrt(ac))
        ys.append(-1.0)
    ax.plot(sd, sf, "o", mfc="none", mec=RED, ms=4, mew=0.8, label="simulation (MDR springs)")
    if len(pd) and len(sd):
        # The preload (the glued contact pressed in without adhesive stress, here far up the Hertz
        # curve) is unloaded at constant radius until the boundary springs reach eq. (12): a straight
        # line into the first detachment. The axes stop short of it; the line shows where it is.
        ax.plot([pd[0], sd[0]], [pf[0], sf[0]], ":", color=GREY, lw=1.0,
                label=rf"unloading from the preload ($\tilde d={pd[0]:.3g}$, $\tilde F={pf[0]:.3g}$)")
    if len(idd):
        ax.plot(idd, iff, "*", color=RED, ms=10,
                label=rf"instability, $\tilde F = {iff[0]:.4f}$"
                + (rf" (analytic ${crit:.4f}$)" if analytic else ""))
        xs.append(idd[0])
        ys.append(iff[0])
    if xs:
        span_x = max(max(xs) - min(xs), 1e-12)
        span_y = max(max(ys) - min(ys), 1e-12)
        ax.set_xlim(min(xs) - 0.1 * span_x, max(xs) + 0.15 * span_x)
        ax.set_ylim(min(ys) - 0.1 * span_y, max(ys) + 0.2 * span_y)
    if run.scales:
        ax.set_xlabel(r"$\tilde d = d/d_0$")
        ax.set_ylabel(r"$\tilde F = F/F_0$")
    else:
        ax.set_xlabel("indentation d [m]")
        ax.set_ylabel("normal force F [N]")
    ax.set_title(f"Fig. 2{panel}: normal adhesive contact, {label}"
                 + (f"\n{run.title}" if run.title and run.profile != EXACT else ""), fontsize=10)
    ax.legend(loc="upper left", fontsize=8)
    ax.grid(alpha=0.3)
    return fig


# --------------------------------------------------------------------------- Fig. 3

class Sweep:
    """The instability rows of a Fig. 3a sweep CSV, in units of (d0, F0) where the engine wrote
    them (its dimensionless columns, from the run's own scales), with the run of its scene."""

    def __init__(self, results, name):
        self.name = name
        self.run = Run(os.path.join(results, f"{name}.json"))
        rows = read_csv(os.path.join(results, f"{name}.csv"))
        rows = [r for r in rows if r.get("status", "instability") == "instability"]
        scaled = bool(rows) and "dimensionless_normal_force" in rows[0]
        prefix = "dimensionless_" if scaled else ""
        get = lambda key: np.array([float(r[prefix + key]) for r in rows])
        self.scaled = scaled
        self.u = get("tangential_displacement")
        self.Fz = get("normal_force")
        self.Fx = get("tangential_force")
        self.d = get("indentation")
        self.analytic, why = self.run.closed_forms()
        if self.analytic and rows and scaled:
            # The JSON must be the sweep's scene: its F0 is the one the engine scaled the rows by.
            f0 = float(rows[0]["normal_force"]) / float(rows[0]["dimensionless_normal_force"])
            if abs(f0 - self.run.scales[0]) > 1e-9 * abs(f0):
                self.analytic = False
                why = (f"{name}.json is not the run of {name}.csv's scene (F0 {self.run.scales[0]:.6g} N, "
                       f"the rows' {f0:.6g} N): no closed forms drawn")
        if why:
            note(why)

    def curve(self, control, n=600):
        """The paper's critical states at the run's G*/E* over the sweep's range of u."""
        u_max = max(self.u.max() if len(self.u) else 0.0, 1e-9)
        states = [ref.critical(control, u, self.run.gamma) for u in np.linspace(0.0, u_max, n)]
        return {k: np.array([s[k] for s in states]) for k in ("u", "Fz", "Fx", "d")}


def plot_by_sign(ax, x, y, d, **kw):
    """A line red where the critical indentation is negative, blue where it is positive (paper Fig. 3a)."""
    neg = d <= 0.0
    for mask, color in ((neg, RED), (~neg, BLUE)):
        # extend each segment by one point so the two colours join
        idx = np.flatnonzero(mask)
        if idx.size == 0:
            continue
        idx = np.unique(np.clip(np.concatenate([idx, idx + 1]), 0, len(x) - 1))
        ax.plot(x[idx], y[idx], color=color, **kw)


def moduli_label(sweeps):
    gammas = sorted({round(s.run.gamma, 6) for s in sweeps})
    return r"$E^*=G^*$" if gammas == [1.0] else ", ".join(rf"$G^*/E^*={g:.4g}$" for g in gammas)


def figure_fig3a(fg, fl):
    fig, ax = plt.subplots(figsize=(6.4, 4.8))
    ax.axhline(0.0, color=GREY, lw=0.6)
    for data, control in ((fg, "fixed-grips"), (fl, "fixed-load")):
        if data.analytic:
            c = data.curve(control)
            plot_by_sign(ax, c["Fx"], c["Fz"], c["d"], lw=1.4)
    styles = [(fg, "D", "*", "fixed grips (normal and tangential)"),
              (fl, "o", "^", "fixed load (normal), fixed grips (tangential)")]
    for data, neg_marker, pos_marker, name in styles:
        neg = data.d <= 0.0
        ax.plot(data.Fx[neg], data.Fz[neg], neg_marker, mfc="none", mec=RED, ms=6,
                label=f"{name}, $d<0$")
        ax.plot(data.Fx[~neg], data.Fz[~neg], pos_marker, mfc="none", mec=BLUE, ms=8 if pos_marker == "*" else 6,
                label=f"{name}, $d>0$")
    if fg.analytic or fl.analytic:
        ax.plot([], [], color=BLACK, lw=1.4, label="analytic: eq. (35) upper, eqs. (25)-(29) lower")
    scaled = fg.scaled and fl.scaled
    ax.set_xlabel(r"$\tilde F_x = F_x/F_0$" if scaled else "tangential force F_x [N]")
    ax.set_ylabel(r"$\tilde F_z = F_z/F_0$" if scaled else "normal force F_z [N]")
    ax.set_title(rf"Fig. 3a: critical normal force against tangential force, {moduli_label([fg, fl])}")
    ax.legend(loc="upper left", fontsize=7.5)
    ax.grid(alpha=0.3)
    return fig


def figure_fig3b(fg, fl):
    """Delta F~z = F~z(fixed grips) - F~z(fixed load) against F~x.

    The paper takes the difference of the two curves of Fig. 3a, i.e. at equal F~x. The simulated
    fixed-grips F~z is interpolated at each fixed-load F~x, linearly in F~x^2 (the fixed-grips curve
    is linear in F~x^2, eq. 34). The difference at equal tangential displacement u~ (the two runs of
    one sweep value) is shown as well, drawn against the fixed-load F~x.
    """
    fig, ax = plt.subplots(figsize=(6.4, 4.8))
    ax.axhline(0.0, color=GREY, lw=0.6)
    if fg.analytic and fl.analytic:
        afl, afg = fl.curve("fixed-load"), fg.curve("fixed-grips")
        # analytic, equal F~x: eq. 34 (at the fixed-grips run's G*/E*) at the fixed-load F~x
        ax.plot(afl["Fx"], ref.master_curve_fixed_grips(afl["Fx"], fg.run.gamma) - afl["Fz"],
                color=BLACK, lw=1.4, label=r"analytic, equal $\tilde F_x$: eq. (34) $-$ eqs. (25)-(29)")
        if len(afg["u"]) == len(afl["u"]) and np.allclose(afg["u"], afl["u"]):
            ax.plot(afl["Fx"], afg["Fz"] - afl["Fz"], color=GREY, lw=1.0, ls="--",
                    label=r"analytic, equal $\tilde u_x^{(0)}$ (against fixed-load $\tilde F_x$)")
        ax.annotate(r"$\Delta\tilde F_z(0) = 4/9$", xy=(0.0, 4.0 / 9.0), xytext=(0.25, 0.48), fontsize=9,
                    arrowprops={"arrowstyle": "->", "lw": 0.7})
        ax.set_ylim(-0.02, 0.52)
    # simulated, equal F~x
    if len(fg.Fx) > 1 and len(fl.Fx):
        order = np.argsort(fg.Fx)
        fx2, fz = fg.Fx[order] ** 2, fg.Fz[order]
        inside = (fl.Fx ** 2 >= fx2[0]) & (fl.Fx ** 2 <= fx2[-1])
        dz = np.interp(fl.Fx[inside] ** 2, fx2, fz) - fl.Fz[inside]
        ax.plot(fl.Fx[inside], dz, "o", mfc="none", mec=RED, ms=6, label=r"simulation, equal $\tilde F_x$")
    # equal u~
    n = min(len(fg.u), len(fl.u))
    same = np.isclose(fg.u[:n], fl.u[:n], rtol=1e-9, atol=1e-12)
    ax.plot(fl.Fx[:n][same], fg.Fz[:n][same] - fl.Fz[:n][same], "^", mfc="none", mec=GREY, ms=5,
            label=r"simulation, equal $\tilde u_x^{(0)}$")
    ax.set_xlabel(r"$\tilde F_x = F_x/F_0$")
    ax.set_ylabel(r"$\Delta\tilde F_z = \tilde F_z^{fg} - \tilde F_z^{fl}$")
    ax.set_title(rf"Fig. 3b: difference of the critical normal forces of Fig. 3a, {moduli_label([fg, fl])}")
    ax.legend(loc="lower left", fontsize=8)
    ax.grid(alpha=0.3)
    return fig


def figure_master_curve(sweeps):
    """Eq. 34: under fixed grips F~z = E* F~x^2/(4 G*) - 5/9 for every Poisson ratio; each
    sweep at its own run's G*/E*."""
    fig, ax = plt.subplots(figsize=(6.4, 4.8))
    xmax = max([(s.Fx ** 2).max() / (4.0 * s.run.gamma) for s in sweeps if len(s.Fx)] + [1e-9])
    x = np.linspace(0.0, xmax, 200)
    ax.plot(x, x - 5.0 / 9.0, color=BLACK, lw=1.4, label=r"eq. (34): $\tilde F_z = X - 5/9$")
    for (sweep, control), (marker, colour) in zip(sweeps.items(), (("D", RED), ("o", GREY), ("s", BLUE))):
        ax.plot(sweep.Fx ** 2 / (4.0 * sweep.run.gamma), sweep.Fz, marker, mfc="none", mec=colour, ms=5,
                label=rf"{control}, $G^*/E^* = {sweep.run.gamma:.4g}$"
                + (" (approaches eq. (35))" if control == "fixed load" else ""))
    ax.set_xlabel(r"$X = \dfrac{E^*}{4G^*}\,\tilde F_x^2$")
    ax.set_ylabel(r"$\tilde F_z = F_z/F_0$")
    ax.set_title("Master curve of the fixed-grips pull-off, eq. (34)")
    ax.legend(loc="upper left", fontsize=8)
    ax.grid(alpha=0.3)
    return fig


def main(argv=None):
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--results", default=os.path.join(root, "results"), help="directory of the runs' output")
    args = parser.parse_args(argv)
    results = args.results

    plt.rcParams.update({"font.size": 10, "svg.fonttype": "none"})

    def attempt(name, make):
        """Draws one figure; a run that is missing or unreadable leaves it out with a note."""
        try:
            save(make(), results, name)
            return True
        except (OSError, KeyError, ValueError, TypeError) as err:
            note(f"{name} left out: {type(err).__name__}: {err}")
            return False

    ok = attempt("fig2a_fixed_grips", lambda: figure_fig2(results, "fixed_grips", "a"))
    ok &= attempt("fig2b_fixed_load", lambda: figure_fig2(results, "fixed_load", "b"))
    try:
        fg, fl = Sweep(results, "fig3a_fixed_grips"), Sweep(results, "fig3a_fixed_load")
    except (OSError, KeyError, ValueError, TypeError) as err:
        note(f"fig3a, fig3b and fig_master_curve left out: {type(err).__name__}: {err}")
        return 1
    ok &= attempt("fig3a", lambda: figure_fig3a(fg, fl))
    ok &= attempt("fig3b", lambda: figure_fig3b(fg, fl))
    sweeps = {fg: "fixed grips", fl: "fixed load"}
    if os.path.exists(os.path.join(results, "fig3a_fixed_grips_nu03.csv")):
        try:
            sweeps[Sweep(results, "fig3a_fixed_grips_nu03")] = "fixed grips"
        except (OSError, KeyError, ValueError, TypeError) as err:
            note(f"fig3a_fixed_grips_nu03 left out of the master curve: {type(err).__name__}: {err}")
    if all(s.analytic and s.scaled for s in sweeps):
        ok &= attempt("fig_master_curve", lambda: figure_master_curve(sweeps))
    else:
        note("fig_master_curve left out: eq. (34) is a parabola's, and a sweep here is not one")
    return 0 if ok else 1


if __name__ == "__main__":
    raise SystemExit(main())
