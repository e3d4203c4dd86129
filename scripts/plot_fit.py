"""The figures of `mdrsim fit --plot` (embedded into the mdrsim binary at build time).

  plot_fit.py curve SAMPLES.csv OUT.png TITLE
      SAMPLES.csv: tip_position [m], force [N], model [N] (empty where the model has none).
      The measured curve and the fit over the indentation axis, and the residuals below.
  plot_fit.py map FITS.csv OUT.png [FILE COLUMNS ROWS WIDTH HEIGHT CENTER_X CENTER_Y]
      FITS.csv: mdrsim fit's CSV. Images of E, the work of adhesion (where fitted) and the
      residual RMS of FILE's curves on its grid (cells from the CSV's column and row), else
      of every curve at its position, else against the curve's number.
"""
import csv
import math
import sys
import textwrap

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def number(text):
    try:
        value = float(text)
    except ValueError:
        return math.nan
    return value if math.isfinite(value) else math.nan


def plot_curve(samples, out, title):
    z, force, model = [], [], []
    with open(samples, newline="") as f:
        for row in csv.DictReader(f):
            z.append(number(row["tip_position"]) * 1e6)
            force.append(number(row["force"]) * 1e9)
            model.append(number(row["model"]) * 1e9)
    residual = [f - m for f, m in zip(force, model)]
    fig, (top, bottom) = plt.subplots(
        2, 1, sharex=True, figsize=(7, 6), gridspec_kw={"height_ratios": [3, 1]}
    )
    top.plot(z, force, ".", ms=2, color="0.5", label="measured")
    top.plot(z, model, "-", lw=1.5, color="C3", label="fit")
    top.set_ylabel("force [nN]")
    top.legend()
    top.set_title(textwrap.fill(title, 100), fontsize=8)
    bottom.plot(z, residual, ".", ms=2, color="C0")
    bottom.axhline(0.0, color="k", lw=0.5)
    bottom.set_ylabel("residual [nN]")
    bottom.set_xlabel("tip position [um] (decreasing into the sample)")
    bottom.invert_xaxis()
    fig.tight_layout()
    fig.savefig(out, dpi=120)


FIELDS = [
    ("youngs_modulus", "E [Pa]", 1.0),
    ("work_of_adhesion", "work of adhesion [J/m^2]", 1.0),
    ("residual_rms", "residual RMS [N]", 1.0),
]


def plot_map(fits, out, grid_file, grid):
    with open(fits, newline="") as f:
        rows = list(csv.DictReader(f))
    if grid_file is not None:
        rows = [r for r in rows if r["file"] == grid_file]
    fields = [
        (key, label) for key, label, _ in FIELDS if any(r.get(key, "") != "" for r in rows)
    ]
    if not fields:
        fields = [("youngs_modulus", "E [Pa]")]
    fig, axes = plt.subplots(1, len(fields), figsize=(4.6 * len(fields), 4.2), squeeze=False)
    fitted = sum(r["status"] == "fitted" for r in rows)
    name = rows[0]["file"].rsplit("/", 1)[-1] if rows else ""
    fig.suptitle(f"{name}: {fitted} of {len(rows)} curves fitted", fontsize=9)
    for ax, (key, label) in zip(axes[0], fields):
        values = [number(r.get(key, "")) if r["status"] == "fitted" else math.nan for r in rows]
        if grid is not None:
            columns, nrows, width, height, cx, cy = grid
            image = [[math.nan] * int(columns) for _ in range(int(nrows))]
            for r, v in zip(rows, values):
                if r["column"] != "" and r["row"] != "":
                    column, row = int(r["column"]), int(r["row"])
                    if 0 <= row < len(image) and 0 <= column < len(image[0]):
                        image[row][column] = v
            extent = [(cx - width / 2) * 1e6, (cx + width / 2) * 1e6,
                      (cy - height / 2) * 1e6, (cy + height / 2) * 1e6]
            shown = ax.imshow(image, origin="lower", extent=extent, interpolation="nearest",
                              cmap="viridis")
            ax.set_xlabel("x [um]")
            ax.set_ylabel("y [um]")
        elif all(r["x"] != "" for r in rows):
            shown = ax.scatter([number(r["x"]) * 1e6 for r in rows],
                               [number(r["y"]) * 1e6 for r in rows], c=values, s=40,
                               cmap="viridis")
            ax.set_xlabel("x [um]")
            ax.set_ylabel("y [um]")
            ax.set_aspect("equal")
        else:
            shown = ax.scatter(range(len(rows)), values, c=values, cmap="viridis")
            ax.set_xlabel("curve")
            ax.set_yscale("log")
        fig.colorbar(shown, ax=ax, label=label)
        ax.set_title(label)
    fig.tight_layout()
    fig.savefig(out, dpi=120)


def main(argv):
    if len(argv) >= 4 and argv[0] == "curve":
        plot_curve(argv[1], argv[2], argv[3])
    elif len(argv) in (3, 10) and argv[0] == "map":
        grid = [float(x) for x in argv[4:10]] if len(argv) == 10 else None
        plot_map(argv[1], argv[2], argv[3] if grid else None, grid)
    else:
        sys.exit(__doc__)


if __name__ == "__main__":
    main(sys.argv[1:])
