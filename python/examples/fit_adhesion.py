"""Fitting the work of adhesion to measurements with mdrsim and scipy.optimize (the inverse problem).

(a) Critical (Fx, Fz) pairs: a sphere glued at a fixed contact radius, a tangential force Fx
    held, then pulled off under fixed load; the pull-off force Fz at each Fx gives the work of
    adhesion and the mode sensitivity lambda of the `mode-dependent` criterion.
(b) A retract force curve F(d): pressed in, then pulled out under fixed grips until it jumps
    off; gives the work of adhesion and the effective modulus E*.

The "measurements" are synthetic: made by mdrsim at known parameters on a finer model than
the fit uses, plus Gaussian noise of 1 % of the largest measured force, with a fixed seed.
The script fails (exit 1) unless the fit recovers every parameter within its tolerance.

    python fit_adhesion.py [--plot fit.png]
"""

import argparse
import sys

import numpy as np
from scipy.optimize import least_squares

import mdrsim

R = 0.01            # sphere radius [m], known from the probe
NOISE = 0.01        # noise: standard deviation / the largest measured |force|
SEED = 10
# Tolerances: about 4 times the fit's standard error at this noise (the "sigma" printed; over
# 200 seeds the errors spread as sigma says, and the largest were 1.6 %, 0.024 and 1.0 %).
TOLERANCE = {"work_of_adhesion": 0.02, "lambda": 0.035, "effective_modulus": 0.015}
RELATIVE = {"work_of_adhesion": True, "lambda": False, "effective_modulus": True}


# (a) Critical (Fx, Fz) pairs, mode-dependent criterion.
def pull_off_scene(work_of_adhesion, lam, tangential_force, rtol):
    """Glued at a = 0.52 mm (about 2 a0), Fx held, pulled off under fixed load; E* = G* = 1 MPa."""
    return {"material": {"effective_modulus": 1.0e6, "work_of_adhesion": work_of_adhesion},
            "profile": {"type": "parabolic", "radius": R},
            "loading": {"preload": {"contact_radius": 5.2e-4},
                        "tangential": {"control": "fixed-load", "force": tangential_force},
                        "normal": {"control": "fixed-load"}},
            "detachment": {"criterion": "mode-dependent", "lambda": lam},
            # rtol: the critical force to that relative accuracy, and smooth in the parameters
            "discretization": {"rtol": rtol}}


def pull_off_forces(params, fx, rtol=1e-4):
    """The critical normal force Fz [N] at each held tangential force in fx [N]."""
    return np.array([mdrsim.run(pull_off_scene(*params, f, rtol), trajectory=False)
                     .critical.normal_force for f in fx])


# (b) A retract curve: approach to 6 um under fixed grips, then retract until separation.
def retract_scene(work_of_adhesion, effective_modulus, springs):
    return {"material": {"effective_modulus": effective_modulus,
                         "work_of_adhesion": work_of_adhesion},
            "profile": {"type": "parabolic", "radius": R},
            "loading": {"stage": [
                {"name": "approach", "normal": {"control": "fixed-grips", "to": 6.0e-6}},
                {"name": "retract", "normal": {"by": -1.0e-6}, "until": "separation"}]},
            "discretization": {"springs": springs}}


def retract_curve(params, springs=2000):
    """The retract path as (d, F), d increasing, from the pull-off (F = 0 there, after the
    jump) up to the deepest point. Between two rows the springs in contact do not change,
    so F is affine in d: straight lines between the rows are exact."""
    c = mdrsim.run(retract_scene(*params, springs)).curve(stage="retract")  # from its start
    keep = ~c["in_cascade"]                               # equilibria only
    return c["indentation"][keep][::-1], c["normal_force"][keep][::-1]      # d increasing


def retract_forces(params, d, springs=2000):
    """F [N] at the indentations d [m]; 0 beyond the pull-off."""
    return np.interp(d, *retract_curve(params, springs), left=0.0)


def fit(model, x, measured, sigma, guess, bounds, names):
    """Least squares on (model - measured) / sigma; returns the fitted values, their
    standard errors from the Jacobian at the optimum (noise sigma known) and the number of
    model evaluations (finite-difference Jacobians included)."""
    calls = []

    def residuals(p):
        calls.append(p)
        return (model(p, x) - measured) / sigma

    res = least_squares(residuals, guess, bounds=bounds, x_scale=np.abs(guess), diff_step=1e-4)
    assert res.success, res.message
    errors = np.sqrt(np.diag(np.linalg.inv(res.jac.T @ res.jac)))
    return dict(zip(names, res.x)), dict(zip(names, errors)), len(calls)


def report(title, truth, fitted, sigma, nfev):
    print(f"{title} ({nfev} model evaluations)")
    print(f"  {'parameter':<18} {'true':>11} {'fitted':>11} {'sigma':>8} {'error':>8} {'tolerance':>9}")
    ok = True
    for name, true in truth.items():
        if RELATIVE[name]:
            error = fitted[name] / true - 1
            cells = f"{sigma[name] / true:>8.2%} {error:>+8.2%} {TOLERANCE[name]:>9.1%}"
        else:
            error = fitted[name] - true
            cells = f"{sigma[name]:>8.4f} {error:>+8.4f} {TOLERANCE[name]:>9.3f}"
        print(f"  {name:<18} {true:>11.6g} {fitted[name]:>11.6g} {cells}")
        ok &= abs(error) <= TOLERANCE[name]
    return ok


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--plot", metavar="PNG", help="draw the data and the fits into this file")
    args = parser.parse_args()
    rng = np.random.default_rng(SEED)

    # (a) Truth: dgamma = 0.042 J/m^2, lambda = 0.35. Fx from 0 to 4 mN (about 2 F0).
    truth_a = {"work_of_adhesion": 0.042, "lambda": 0.35}
    fx = np.linspace(0.0, 4.0e-3, 9)
    exact = pull_off_forces(list(truth_a.values()), fx, rtol=1e-7)
    sigma_a = NOISE * np.abs(exact).max()
    fz = exact + rng.normal(0.0, sigma_a, fx.size)
    fitted_a, errors_a, nfev = fit(pull_off_forces, fx, fz, sigma_a, [0.1, 0.8],
                                   ([0.01, 0.0], [1.0, 1.0]), list(truth_a))
    ok = report(f"(a) {fx.size} critical (Fx, Fz) pairs, mode-dependent", truth_a, fitted_a,
                errors_a, nfev)

    # (b) Truth: dgamma = 0.042 J/m^2, E* = 1.3 MPa. 40 samples of the retract curve, from
    # the deepest point down to just before the pull-off (where a measured curve ends).
    truth_b = {"work_of_adhesion": 0.042, "effective_modulus": 1.3e6}
    d_true, f_true = retract_curve(list(truth_b.values()), springs=16000)
    d = np.linspace(d_true[0], d_true[-1], 41)[1:]
    exact = np.interp(d, d_true, f_true)
    sigma_b = NOISE * np.abs(exact).max()
    f = exact + rng.normal(0.0, sigma_b, d.size)
    fitted_b, errors_b, nfev = fit(retract_forces, d, f, sigma_b, [0.1, 2.0e6],
                                   ([0.005, 1e5], [1.0, 1e8]), list(truth_b))
    ok &= report(f"(b) a retract curve F(d), {d.size} samples", truth_b, fitted_b, errors_b, nfev)

    print(f"noise: {NOISE:.0%} of the largest |force|, seed {SEED}; "
          + ("every parameter within tolerance" if ok else "FAILED: a parameter is out of tolerance"))

    if args.plot:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, (left, right) = plt.subplots(1, 2, figsize=(10, 4))
        fine = np.linspace(fx[0], fx[-1], 41)
        left.plot(fx * 1e3, fz * 1e3, "o", label="measured")
        left.plot(fine * 1e3, pull_off_forces(list(fitted_a.values()), fine) * 1e3, label="fit")
        left.set(xlabel="Fx [mN]", ylabel="critical Fz [mN]", title="(a) pull-off under shear")
        right.plot(d * 1e6, f * 1e3, "o", label="measured")
        d_fit, f_fit = retract_curve(list(fitted_b.values()))
        right.plot(d_fit * 1e6, f_fit * 1e3, label="fit")
        right.set(xlabel="d [um]", ylabel="F [mN]", title="(b) retract curve")
        for ax in (left, right):
            ax.legend()
        fig.tight_layout()
        fig.savefig(args.plot, dpi=100)
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
