"""Result.plot: the force-displacement path with its jumps and critical point (matplotlib)."""


def plot_result(result, ax=None):
    try:
        import matplotlib.pyplot as plt
    except ImportError as e:
        raise ImportError("Result.plot needs matplotlib, which is not installed "
                          "(Debian: apt-get install python3-matplotlib)") from e
    if ax is None:
        _, ax = plt.subplots()
    scales = result.scales
    d_scale, f_scale = (scales["depth"], scales["force"]) if scales else (1.0, 1.0)
    t = result.trajectory
    if t is not None and len(t["indentation"]):
        # Rows inside a cascade are not equilibria: the jumps are drawn on their own.
        keep = ~t["in_cascade"]
        ax.plot(t["indentation"][keep] / d_scale, t["normal_force"][keep] / f_scale,
                lw=1.2, color="C0", label="path")
    for i, jump in enumerate(j for j in result.jumps if j.after is not None):
        ax.plot([jump.critical.indentation / d_scale, jump.after.indentation / d_scale],
                [jump.critical.normal_force / f_scale, jump.after.normal_force / f_scale],
                ls="--", lw=1.0, color="C3", label="jump" if i == 0 else None)
    if result.critical is not None:
        c = result.critical
        ax.plot([c.indentation / d_scale], [c.normal_force / f_scale], "o", color="C3",
                label=f"critical: F = {c.normal_force / f_scale:.4g}" + (" F0" if scales else " N"))
    ax.axhline(0.0, color="0.7", lw=0.6)
    ax.set_xlabel("indentation d/d0" if scales else "indentation d [m]")
    ax.set_ylabel("normal force F/F0" if scales else "normal force F [N]")
    ax.set_title(result.status)
    ax.legend(loc="best", fontsize="small")
    return ax

