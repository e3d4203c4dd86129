"""Result.plot: the force-displacement path with its jumps and critical point (matplotlib)."""

import math

# What each view draws: (state field, symbol, axis label) for x, then for y.
VIEWS = {
    "normal": (("indentation", "d", "indentation d"), ("normal_force", "F", "normal force F")),
    "tangential": (("tangential_displacement", "u_x", "tangential displacement u_x"),
                   ("tangential_force", "F_x", "tangential force F_x")),
}

# A jump's far end beyond this many path spans from the path is drawn to the frame's edge
# and named there, so that the path itself keeps the axes (a fixed-load pull-off "lands" at
# thousands of d0 once no spring holds the indenter).
_FAR = 0.5
_MARGIN = 0.05


def _range(values):
    finite = [v for v in values if math.isfinite(v)]
    if not finite:
        return None
    return min(finite), max(finite)


def _limits(lo, hi, extra, fallback):
    """The path's range [lo, hi] with a margin, widened to the values of `extra` near it."""
    span = hi - lo
    if not span > 0.0:
        span = max(abs(lo), abs(hi), fallback)
    near = [v for v in extra if math.isfinite(v) and lo - _FAR * span <= v <= hi + _FAR * span]
    lo, hi = min([lo] + near), max([hi] + near)
    span = hi - lo if hi > lo else span
    return lo - _MARGIN * span, hi + _MARGIN * span


def _clip_to(x0, y0, x1, y1, xlim, ylim):
    """Where the segment from (x0, y0), inside the frame, leaves it towards (x1, y1)."""
    t = 1.0
    for start, end, (lo, hi) in ((x0, x1, xlim), (y0, y1, ylim)):
        if end < lo:
            t = min(t, (lo - start) / (end - start))
        elif end > hi:
            t = min(t, (hi - start) / (end - start))
    return x0 + t * (x1 - x0), y0 + t * (y1 - y0)


def plot_result(result, ax=None, view="normal"):
    if view not in VIEWS:
        raise ValueError(f"unknown view '{view}' (known: {', '.join(VIEWS)})")
    (x_field, x_symbol, x_label), (y_field, y_symbol, y_label) = VIEWS[view]
    try:
        import matplotlib.pyplot as plt
    except ImportError as e:
        raise ImportError("Result.plot needs matplotlib, which is not installed "
                          "(Debian: apt-get install python3-matplotlib)") from e
    if ax is None:
        _, ax = plt.subplots()
    scales = result.scales
    d_scale, f_scale = (scales["depth"], scales["force"]) if scales else (1.0, 1.0)
    d_unit, f_unit = (" d0", " F0") if scales else (" m", " N")

    # The equilibria: rows inside a cascade are not, and the jumps are drawn on their own.
    xs, ys = [], []
    t = result.trajectory
    if t is not None and len(t[x_field]):
        keep = ~t["in_cascade"]
        xs = (t[x_field][keep] / d_scale).tolist()
        ys = (t[y_field][keep] / f_scale).tolist()
        ax.plot(xs, ys, lw=1.2, color="C0", label="path")
    # Without a trajectory the path is its stage ends in contact. (A fixed-load pull-off ends
    # its stage where no spring holds the indenter any more: far away, and no equilibrium.)
    states = [j.critical for j in result.jumps]
    if not xs:
        states += [s.end for s in result.stages if s.end.springs_in_contact > 0]
    if result.critical is not None:
        states.append(result.critical)

    def point(state):
        return getattr(state, x_field) / d_scale, getattr(state, y_field) / f_scale

    xs_all = xs + [point(s)[0] for s in states]
    ys_all = ys + [point(s)[1] for s in states]
    # A jump whose indenter separated or slid away under a fixed load has no state after it.
    landed = [j for j in result.jumps if j.after is not None]
    jump_ends = [point(j.after) for j in landed]
    xr, yr = _range(xs_all), _range(ys_all + [0.0])
    if xr is None:  # no state at all: the jumps alone
        xr, yr = _range([x for x, _ in jump_ends]) or (0.0, 1.0), (-1.0, 1.0)
    xlim = _limits(*xr, [x for x, _ in jump_ends], 1.0)
    ylim = _limits(*yr, [y for _, y in jump_ends], 1.0)

    for i, jump in enumerate(landed):
        x0, y0 = point(jump.critical)
        x1, y1 = jump_ends[i]
        inside = xlim[0] <= x1 <= xlim[1] and ylim[0] <= y1 <= ylim[1]
        xe, ye = (x1, y1) if inside else _clip_to(x0, y0, x1, y1, xlim, ylim)
        ax.plot([x0, xe], [y0, ye], ls="--", lw=1.0, color="C3", label="jump" if i == 0 else None)
        if not inside:
            ax.annotate(f"to {x_symbol} = {x1:.4g}{d_unit}, {y_symbol} = {y1:.4g}{f_unit}",
                        xy=(xe, ye),
                        xytext=(4 if xe <= xlim[0] else -4, 4), textcoords="offset points",
                        ha="left" if xe <= xlim[0] else "right", va="bottom", fontsize="small",
                        color="C3")
    if result.critical is not None:
        x, y = point(result.critical)
        ax.plot([x], [y], "o", color="C3", label=f"critical: {y_symbol} = {y:.4g}{f_unit}")
    ax.axhline(0.0, color="0.7", lw=0.6)
    ax.set_xlim(*xlim)
    ax.set_ylim(*ylim)
    ax.set_xlabel(f"{x_label} / d0" if scales else f"{x_label} [m]")
    ax.set_ylabel(f"{y_label} / F0" if scales else f"{y_label} [N]")
    head = f"{result.title}\n" if result.title else ""
    ax.set_title(f"{head}{result.status}, {result.springs} springs", fontsize="medium")
    ax.grid(True, lw=0.4, color="0.9")
    ax.legend(loc="best", fontsize="small")
    return ax
