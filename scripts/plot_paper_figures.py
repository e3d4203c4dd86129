#!/usr/bin/python3
"""Draws the paper's Figs. 2a, 2b, 3a, 3b (and a master-curve check of eq. 34) from mdrsim output.

Run with Debian's Python, which has numpy and matplotlib:
    /usr/bin/python3 scripts/plot_paper_figures.py [--results results] [--scenes scenes]

Reads (written by scripts/reproduce.sh into the results directory):
    fig2_fixed_grips.csv, fig2_fixed_load.csv     trajectories of `mdrsim run --trajectory`
    fig3a_fixed_grips.csv, fig3a_fixed_load.csv    sweeps of `mdrsim sweep` over u (nu = 0)
    fig3a_fixed_grips_nu03.csv                     the fixed-grips sweep at nu = 0.3
Writes PNG and SVG next to them:
    fig2a_fixed_grips, fig2b_fixed_load, fig3a, fig3b, fig_master_curve
Lines are the paper's closed forms (scripts/paper_reference.py, independent of the engine);
markers are the simulation. Prints one line per figure written.
"""

import argparse
import csv
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import paper_reference as ref  # noqa: E402

NU_03 = 0.3           # Poisson ratio of the fig3a_fixed_grips_nu03 sweep (reproduce.sh --set)
MARKERS_FIG2 = 200    # simulated points drawn per Fig. 2 panel
# The scenes' material when the scene file cannot be read (R = 1 cm, E* = 1 MPa, dgamma = 0.05 J/m^2).
DEFAULT_SCENE = {"radius": 0.01, "effective_modulus": 1.0e6, "work_of_adhesion": 0.05}

RED, BLUE, BLACK, GREY = "#c0392b", "#1f4e9c", "black", "#7f7f7f"


def read_csv(path):
    # A sweep CSV starts with its identity line "# mdrsim sweep: ..." (docs/sweeps.md).
    with open(path, newline="") as f:
        return list(csv.DictReader(line for line in f if not line.startswith("#")))


def scene_parameters(path):
    """R, E*, dgamma of a parabolic scene, read independently of the engine (Python 3.11 tomllib)."""
    try:
        import tomllib
        with open(path, "rb") as f:
            scene = tomllib.load(f)
    except (ImportError, OSError) as err:
        print(f"plot: cannot read {path} ({err}); using R = 1 cm, E* = 1 MPa, dgamma = 0.05", file=sys.stderr)
        return dict(DEFAULT_SCENE)
    mat, prof = scene["material"], scene["profile"]
    if "effective_modulus" in mat:
        es = mat["effective_modulus"]
    else:
        es, _ = ref.effective_moduli(mat["youngs_modulus"], mat.get("poisson_ratio", 0.0))
    return {"radius": prof["radius"], "effective_modulus": es, "work_of_adhesion": mat["work_of_adhesion"]}


def save(fig, results, name):
    for ext in ("png", "svg"):
        path = os.path.join(results, f"{name}.{ext}")
        fig.savefig(path, dpi=150 if ext == "png" else None, bbox_inches="tight")
    plt.close(fig)
    print(f"plot: wrote {os.path.join(results, name)}.png and .svg")


# --------------------------------------------------------------------------- Fig. 2

def trajectory_points(rows, f0, d0):
    """Equilibrium states of a trajectory in paper units, subsampled to about MARKERS_FIG2 markers.

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
    if len(d) > MARKERS_FIG2:
        # evenly spaced along the curve as drawn (detachments are evenly spaced in a, which
        # crowds the markers where the curve turns)
        s = np.concatenate([[0.0], np.cumsum(np.hypot(np.diff(d) / np.ptp(d), np.diff(f) / np.ptp(f)))])
        idx = np.unique(np.searchsorted(s, np.linspace(0.0, s[-1], MARKERS_FIG2)).clip(0, len(d) - 1))
        d, f = d[idx], f[idx]
    return conv(preload), (d, f), conv(instab)


def plot_fig2(results, scenes, control, panel):
    rows = read_csv(os.path.join(results, f"fig2_{control}.csv"))
    p = scene_parameters(os.path.join(scenes, f"fig2_{control.replace('-', '_')}.toml"))
    f0, a0, d0 = ref.scales(p["radius"], p["effective_modulus"], p["work_of_adhesion"])
    (pd, pf), (sd, sf), (idd, iff) = trajectory_points(rows, f0, d0)
    a_max = max(2.0, float(rows[0]["contact_radius"]) / a0) if rows else 2.0

    a = np.linspace(0.0, a_max, 2000)
    crit = ref.JKR_PULL_OFF_FIXED_GRIPS if control == "fixed_grips" else ref.JKR_PULL_OFF_FIXED_LOAD
    label = "fixed grips" if control == "fixed_grips" else "fixed load"

    fig, ax = plt.subplots(figsize=(6.0, 4.5))
    ax.axhline(0.0, color=GREY, lw=0.6)
    ax.axvline(0.0, color=GREY, lw=0.6)
    ax.plot(3 * a ** 2 - 4 * np.sqrt(a), a ** 3 - 2 * a ** 1.5, color=BLACK, lw=1.4,
            label="analytic, eqs. (18)-(19)")
    ax.plot(sd, sf, "o", mfc="none", mec=RED, ms=4, mew=0.8, label="simulation (MDR springs)")
    if len(pd) and len(sd):
        # The preload (the glued contact pressed in without adhesive stress, here far up the Hertz
        # curve) is unloaded at constant radius until the boundary springs reach eq. (12): a straight
        # line into the first detachment. The axes stop short of it; the line shows where it is.
        ax.plot([pd[0], sd[0]], [pf[0], sf[0]], ":", color=GREY, lw=1.0,
                label=rf"unloading from the preload ($\tilde d={pd[0]:.3g}$, $\tilde F={pf[0]:.3g}$)")
    if len(idd):
        ax.plot(idd, iff, "*", color=RED, ms=10,
                label=rf"instability, $\tilde F = {iff[0]:.4f}$ (analytic ${crit:.4f}$)")
    ax.axhline(crit, color=BLUE, lw=0.8, ls="--")
    dmin = 3 * ref.critical_radius_fixed_grips(0.0) ** 2 - 4 * math.sqrt(ref.critical_radius_fixed_grips(0.0))
    xs = np.concatenate([sd, [dmin]])
    ys = np.concatenate([sf, [-1.0]])
    ax.set_xlim(xs.min() - 0.6, xs.max() + 0.8)
    ax.set_ylim(ys.min() - 0.3, ys.max() + 0.6)
    ax.set_xlabel(r"$\tilde d = d/d_0$")
    ax.set_ylabel(r"$\tilde F = F/F_0$")
    ax.set_title(f"Fig. 2{panel}: normal adhesive contact, {label}")
    ax.legend(loc="upper left", fontsize=8)
    ax.grid(alpha=0.3)
    save(fig, results, f"fig2{panel}_{control}")


# --------------------------------------------------------------------------- Fig. 3

def sweep(results, name):
    rows = read_csv(os.path.join(results, name))
    rows = [r for r in rows if r.get("status", "instability") == "instability"]
    get = lambda key: np.array([float(r[key]) for r in rows])
    return {"u": get("dimensionless_tangential_displacement"),
            "Fz": get("dimensionless_normal_force"),
            "Fx": get("dimensionless_tangential_force"),
            "d": get("dimensionless_indentation")}


def analytic_curve(control, u_max, gamma=1.0, n=600):
    states = [ref.critical(control, u, gamma) for u in np.linspace(0.0, u_max, n)]
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


def plot_fig3a(results, fg, fl):
    u_max = max(fg["u"].max(), fl["u"].max(), 1e-9)
    afg, afl = analytic_curve("fixed-grips", u_max), analytic_curve("fixed-load", u_max)

    fig, ax = plt.subplots(figsize=(6.4, 4.8))
    ax.axhline(0.0, color=GREY, lw=0.6)
    plot_by_sign(ax, afg["Fx"], afg["Fz"], afg["d"], lw=1.4)
    plot_by_sign(ax, afl["Fx"], afl["Fz"], afl["d"], lw=1.4)
    styles = [(fg, "D", "*", "fixed grips (normal and tangential)"),
              (fl, "o", "^", "fixed load (normal), fixed grips (tangential)")]
    for data, neg_marker, pos_marker, name in styles:
        neg = data["d"] <= 0.0
        ax.plot(data["Fx"][neg], data["Fz"][neg], neg_marker, mfc="none", mec=RED, ms=6,
                label=f"{name}, $d<0$")
        ax.plot(data["Fx"][~neg], data["Fz"][~neg], pos_marker, mfc="none", mec=BLUE, ms=8 if pos_marker == "*" else 6,
                label=f"{name}, $d>0$")
    ax.plot([], [], color=BLACK, lw=1.4, label="analytic: eq. (35) upper, eqs. (25)-(29) lower")
    ax.set_xlabel(r"$\tilde F_x = F_x/F_0$")
    ax.set_ylabel(r"$\tilde F_z = F_z/F_0$")
    ax.set_title(r"Fig. 3a: critical normal force against tangential force, $E^*=G^*$")
    ax.legend(loc="upper left", fontsize=7.5)
    ax.grid(alpha=0.3)
    save(fig, results, "fig3a")


def plot_fig3b(results, fg, fl):
    """Delta F~z = F~z(fixed grips) - F~z(fixed load) against F~x.

    The paper takes the difference of the two curves of Fig. 3a, i.e. at equal F~x. The simulated
    fixed-grips F~z is interpolated at each fixed-load F~x, linearly in F~x^2 (the fixed-grips curve
    is linear in F~x^2, eq. 35). The difference at equal tangential displacement u~ (the two runs of
    one sweep value) is shown as well, drawn against the fixed-load F~x.
    """
    u_max = max(fg["u"].max(), fl["u"].max(), 1e-9)
    afl = analytic_curve("fixed-load", u_max)
    afg = analytic_curve("fixed-grips", u_max)

    fig, ax = plt.subplots(figsize=(6.4, 4.8))
    ax.axhline(0.0, color=GREY, lw=0.6)
    # analytic, equal F~x: eq. 35 at the fixed-load F~x minus the fixed-load F~z
    ax.plot(afl["Fx"], ref.master_curve_fixed_grips(afl["Fx"]) - afl["Fz"], color=BLACK, lw=1.4,
            label=r"analytic, equal $\tilde F_x$: eq. (35) $-$ eqs. (25)-(29)")
    # simulated, equal F~x
    order = np.argsort(fg["Fx"])
    fx2, fz = fg["Fx"][order] ** 2, fg["Fz"][order]
    inside = (fl["Fx"] ** 2 >= fx2[0]) & (fl["Fx"] ** 2 <= fx2[-1])
    dz = np.interp(fl["Fx"][inside] ** 2, fx2, fz) - fl["Fz"][inside]
    ax.plot(fl["Fx"][inside], dz, "o", mfc="none", mec=RED, ms=6, label=r"simulation, equal $\tilde F_x$")
    # equal u~
    n = min(len(fg["u"]), len(fl["u"]))
    same = np.isclose(fg["u"][:n], fl["u"][:n], rtol=1e-9, atol=1e-12)
    ax.plot(afl["Fx"], afg["Fz"] - afl["Fz"], color=GREY, lw=1.0, ls="--",
            label=r"analytic, equal $\tilde u_x^{(0)}$ (against fixed-load $\tilde F_x$)")
    ax.plot(fl["Fx"][:n][same], fg["Fz"][:n][same] - fl["Fz"][:n][same], "^", mfc="none", mec=GREY, ms=5,
            label=r"simulation, equal $\tilde u_x^{(0)}$")
    ax.annotate(r"$\Delta\tilde F_z(0) = 4/9$", xy=(0.0, 4.0 / 9.0), xytext=(0.25, 0.48), fontsize=9,
                arrowprops={"arrowstyle": "->", "lw": 0.7})
    ax.set_ylim(-0.02, 0.52)
    ax.set_xlabel(r"$\tilde F_x = F_x/F_0$")
    ax.set_ylabel(r"$\Delta\tilde F_z = \tilde F_z^{fg} - \tilde F_z^{fl}$")
    ax.set_title(r"Fig. 3b: difference of the critical normal forces of Fig. 3a")
    ax.legend(loc="lower left", fontsize=8)
    ax.grid(alpha=0.3)
    save(fig, results, "fig3b")


def plot_master_curve(results, fg, fl, fg03):
    """Eq. 34: under fixed grips F~z = E* F~x^2/(4 G*) - 5/9 for every Poisson ratio."""
    g03 = ref.gamma_from_nu(NU_03)
    fig, ax = plt.subplots(figsize=(6.4, 4.8))
    xmax = max((fg["Fx"] ** 2).max() / 4.0, (fg03["Fx"] ** 2).max() / (4.0 * g03), (fl["Fx"] ** 2).max() / 4.0)
    x = np.linspace(0.0, xmax, 200)
    ax.plot(x, x - 5.0 / 9.0, color=BLACK, lw=1.4, label=r"eq. (34): $\tilde F_z = X - 5/9$")
    ax.plot(fg["Fx"] ** 2 / 4.0, fg["Fz"], "D", mfc="none", mec=RED, ms=6,
            label=r"fixed grips, $\nu = 0$ ($G^*/E^* = 1$)")
    ax.plot(fg03["Fx"] ** 2 / (4.0 * g03), fg03["Fz"], "s", mfc="none", mec=BLUE, ms=5,
            label=rf"fixed grips, $\nu = {NU_03}$ ($G^*/E^* = {g03:.4f}$)")
    ax.plot(fl["Fx"] ** 2 / 4.0, fl["Fz"], "o", mfc="none", mec=GREY, ms=5,
            label=r"fixed load, $\nu = 0$ (approaches eq. (35))")
    ax.set_xlabel(r"$X = \dfrac{E^*}{4G^*}\,\tilde F_x^2$")
    ax.set_ylabel(r"$\tilde F_z = F_z/F_0$")
    ax.set_title("Master curve of the fixed-grips pull-off, eq. (34)")
    ax.legend(loc="upper left", fontsize=8)
    ax.grid(alpha=0.3)
    save(fig, results, "fig_master_curve")


def main(argv=None):
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--results", default=os.path.join(root, "results"), help="directory of the runs' output")
    parser.add_argument("--scenes", default=os.path.join(root, "scenes"), help="directory of the Fig. 2 scenes")
    args = parser.parse_args(argv)

    plt.rcParams.update({"font.size": 10, "svg.fonttype": "none"})
    plot_fig2(args.results, args.scenes, "fixed_grips", "a")
    plot_fig2(args.results, args.scenes, "fixed_load", "b")
    fg = sweep(args.results, "fig3a_fixed_grips.csv")
    fl = sweep(args.results, "fig3a_fixed_load.csv")
    plot_fig3a(args.results, fg, fl)
    plot_fig3b(args.results, fg, fl)
    nu03 = os.path.join(args.results, "fig3a_fixed_grips_nu03.csv")
    if os.path.exists(nu03):
        plot_master_curve(args.results, fg, fl, sweep(args.results, "fig3a_fixed_grips_nu03.csv"))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
