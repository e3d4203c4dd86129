"""Measured force curves: an instrument's file read into NumPy arrays, and a curve fitted.

    import mdrsim
    curve = mdrsim.afm.load("tests/data/afm/fmt-jpk-fd_spot3-0192.jpk-force")[0]
    curve.segment("approach").force                     # [N], NumPy
    fit = mdrsim.afm.fit(curve, model="hertz", tip="parabolic:radius=1e-5")
    fit.youngs_modulus.value, fit.youngs_modulus.standard_error
    fit.plot()

The readers and the fit are the engine's (engine/measured, engine/fit), the same that
`mdrsim fit` runs: Fit.to_dict() is its --json object, number for number. A file that cannot be
read, or bad arguments, raise mdrsim.SceneError (a ValueError) with one line (docs/afm.md).
"""

import json
import logging
import os
import time
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass

from . import _core
from ._core import SceneError

__all__ = ["Calibrated", "Curve", "Fit", "FitParameter", "MapPosition", "Segment", "fit",
           "fit_files", "load"]

_log = logging.getLogger("mdrsim")
_PROGRESS_SECONDS = 10.0


@dataclass(frozen=True)
class Calibrated:
    """A calibration value and where it came from (a property key, a note line, an override)."""

    value: float
    source: str


@dataclass(frozen=True)
class MapPosition:
    """Where on the sample a curve of a map was taken: x, y [m] and the file's index."""

    x: float
    y: float
    index: int


class Segment:
    """One part of a curve (approach, retract or pause) as NumPy arrays, each None where the
    file does not give it. Heights follow afmformats' sign (they decrease towards the sample).

    time [s], piezo_height [m], measured_height [m], deflection [m]: as the file gives them;
    tip_position [m]: height + deflection (the height sensor's reading where the file has one,
    else the piezo's), as the fit uses it; force [N]: the file's, else deflection x spring
    constant.
    """

    __slots__ = ("name", "kind", "time", "piezo_height", "measured_height", "deflection",
                 "tip_position", "force")

    def __init__(self, raw):
        for key in self.__slots__:
            setattr(self, key, raw[key])

    def __len__(self):
        for key in ("tip_position", "force", "piezo_height", "measured_height", "deflection",
                    "time"):
            value = getattr(self, key)
            if value is not None:
                return len(value)
        return 0

    def __repr__(self):
        return f"<mdrsim.afm.Segment {self.name!r} ({self.kind}), {len(self)} samples>"


class Curve:
    """One force curve of a file: its segments, calibration and map position.

    file: the path as given to load(); label: where in the file ("index/109" of a map, "" for
    a file of one curve); unreadable: "" or, in a map, why this curve could not be read (it
    then has no segments, and fit() raises with that line).
    """

    def __init__(self, file, file_format, raw):
        self._handle = raw["handle"]
        self.file = file
        self.format = file_format
        self.label = raw["label"]
        self.unreadable = raw["unreadable"]
        self.segments = [Segment(s) for s in raw["segments"]]
        self.calibration = {key: None if value is None else Calibrated(**value)
                            for key, value in raw["calibration"].items()}
        position = raw["position"]
        self.position = None if position is None else MapPosition(*position)

    @property
    def segment_names(self):
        """The segments' names as the file gives them (JPK "extend-spm", else the kind)."""
        return [s.name for s in self.segments]

    def segment(self, kind):
        """The first segment of `kind` ("approach", "retract" or "pause"), as the fit takes it."""
        for s in self.segments:
            if s.kind == kind:
                return s
        raise KeyError(f"{kind!r}: no such segment (the curve has: "
                       f"{', '.join(s.kind for s in self.segments) or 'none'})")

    @property
    def spring_constant(self):
        """[N/m] or None."""
        c = self.calibration["spring_constant"]
        return None if c is None else c.value

    @property
    def sensitivity(self):
        """[m/V] or None."""
        c = self.calibration["sensitivity"]
        return None if c is None else c.value

    def __repr__(self):
        where = f"[{self.label}]" if self.label else ""
        parts = ", ".join(f"{s.name} {len(s)}" for s in self.segments) or self.unreadable
        return f"<mdrsim.afm.Curve {os.path.basename(self.file)}{where}: {parts}>"


def load(path, sensitivity=None, spring_constant=None):
    """Every curve of a measured file as a list of Curve (one for a single force curve, one per
    point of a map). sensitivity [m/V] and spring_constant [N/m] replace or supply the file's,
    as `mdrsim fit --fix sensitivity=...` does. Formats: docs/afm.md.

    Raises mdrsim.SceneError with the reader's one line for a file that cannot be read."""
    raw = _core.afm_read(os.fspath(path), sensitivity, spring_constant)
    return [Curve(raw["path"], raw["format"], c) for c in raw["curves"]]


@dataclass(frozen=True)
class FitParameter:
    """A fitted (or held) parameter: value and standard error (None without a fit; the error is
    0 for a held one)."""

    value: float
    standard_error: float
    fixed: bool


class Fit:
    """One curve's fit: the fields of `mdrsim fit --json` as attributes (to_dict() gives that
    object), and the data and fitted model as arrays for plotting.

    status: "fitted", "no-contact", "not-converged" or "unreadable"; message: why, or "".
    warnings: what a fitted curve's fit cannot vouch for, one line each (a baseline its record
    does not fix, a residual far above its noise; docs/afm.md "Warnings"), else [].
    tip_position [m], force [N]: the fitted segment as prepared (None without a fit);
    fitted_force [N]: the model at the fitted values at each tip position.
    """

    def __init__(self, document, tip_position, force, fitted_force):
        self._document = document
        self.tip_position = tip_position
        self.force = force
        self.fitted_force = fitted_force

    def to_dict(self):
        """The JSON object `mdrsim fit --json` writes for this curve."""
        return json.loads(json.dumps(self._document))

    def __getattr__(self, name):
        document = self.__dict__.get("_document")
        if document is None or name not in document:
            raise AttributeError(name)
        value = document[name]
        if isinstance(value, dict) and "fixed" in value:
            return FitParameter(value["value"], value["standard_error"], value["fixed"])
        return value

    @property
    def message(self):
        return self._document.get("message", "")

    def __dir__(self):
        return sorted(set(super().__dir__()) | set(self._document))

    @property
    def indentation(self):
        """[m] contact_point - tip_position (None without a fit)."""
        if self.tip_position is None or self._document["contact_point"]["value"] is None:
            return None
        return self._document["contact_point"]["value"] - self.tip_position

    def plot(self, ax=None):
        """Force against indentation, the data as dots and the fitted model as a line (nN
        against um). Needs matplotlib; returns the Axes."""
        if ax is None:
            import matplotlib.pyplot as plt
            ax = plt.figure().add_subplot()
        if self.indentation is None:
            raise ValueError(f"nothing to plot: the fit's status is {self.status}")
        ax.plot(self.indentation * 1e6, self.force * 1e9, ".", ms=2, label="measured")
        ax.plot(self.indentation * 1e6, self.fitted_force * 1e9, "-",
                label=f"{self.model}, E = {self.youngs_modulus.value:.4g} Pa")
        ax.set(xlabel="indentation [um]", ylabel="force [nN]",
               title=os.path.basename(self.file) + (f"[{self.curve}]" if self.curve else ""))
        ax.legend()
        return ax

    def __repr__(self):
        e = self._document["youngs_modulus"]["value"]
        shown = "" if e is None else f", E={e:.6g} Pa"
        return f"<mdrsim.afm.Fit {self.status} {self.model}{shown}>"


def _fixed(fix):
    """fit()'s fix as {name: float}; a value that is not a number raises SceneError."""
    fixed = {}
    for key, value in (fix or {}).items():
        try:
            fixed[str(key)] = float(value)
        except (TypeError, ValueError):
            raise SceneError(f"fix {key}: {value!r} is not a number") from None
    return fixed


def fit(curve, model="hertz", tip="parabolic:radius=1e-5", poisson_ratio=0.5,
        segment="approach", fix=None):
    """Fits one Curve by the engine's fit (`mdrsim fit` with the same options) and returns a Fit.

    model: "hertz", "dmt", "jkr", "maugis" or "auto"; tip: "parabolic:radius=R",
    "sphere:radius=R", "cone:half_angle_deg=A", "pyramid:half_angle_deg=A" or a scene file
    (the command's --tip); segment: "approach" or "retract"; fix: a dict holding parameters at
    given values (youngs_modulus [Pa], work_of_adhesion [J/m^2], maugis_parameter (maugis,
    auto), contact_point [m], baseline_offset [N], baseline_slope [N/m]); the calibration is given to
    load(). A curve that cannot be fitted gets its status; bad arguments, and a curve that
    cannot be prepared (no such segment, no spring constant), raise mdrsim.SceneError."""
    if not isinstance(curve, Curve):
        raise TypeError(f"fit: expected an mdrsim.afm.Curve (from mdrsim.afm.load), "
                        f"got {type(curve).__name__}")
    text, tip_position, force, fitted_force = _core.afm_fit(
        curve._handle, str(model), str(tip), float(poisson_ratio), str(segment), _fixed(fix))
    return Fit(json.loads(text), tip_position, force, fitted_force)


def _fit_file(path, options):
    """One task of fit_files: every curve of one file, as the command's JSON objects (plain
    dicts, so that a task's result pickles for a process pool or a Dask cluster)."""
    path = os.fspath(path)
    try:
        curves = load(path, options["sensitivity"], options["spring_constant"])
    except SceneError as error:
        return [{"file": path, "curve": "", "status": "unreadable", "message": str(error)}]
    documents = []
    for curve in curves:
        try:
            documents.append(fit(curve, **options["fit"]).to_dict())
        except SceneError as error:
            documents.append({"file": path, "curve": curve.label, "status": "unreadable",
                              "message": str(error)})
    return documents


def fit_files(paths, executor=None, sensitivity=None, spring_constant=None, **fit_options):
    """Fits every curve of every file in paths, one task per file, and returns the command's
    JSON objects (dicts, as Fit.to_dict()) in the order given: the files, and in each its
    curves. fit_options are fit()'s (model, tip, poisson_ratio, segment, fix); sensitivity and
    spring_constant are load()'s.

    executor: any concurrent.futures.Executor (a Dask cluster: Client.get_executor(), a
    ProcessPoolExecutor); None runs the files on a ThreadPoolExecutor of one thread per CPU
    this process may use (the reading and fitting release the GIL). Bad options raise
    mdrsim.SceneError before any task is sent. A file that cannot be read, or a curve that
    cannot be prepared, gets a dict with status "unreadable" and the reader's line as message:
    a study goes on past a bad file. A long run says how far it is every 10 s ("fit: 57 of 200
    files in 10 s") to the logging logger "mdrsim" at INFO, as sweep() does."""
    paths = [os.fspath(p) for p in paths]
    unknown = sorted(set(fit_options) - {"model", "tip", "poisson_ratio", "segment", "fix"})
    if unknown:
        raise SceneError(f"fit_files: unknown option {unknown[0]!r} (known: model, tip, "
                         f"poisson_ratio, segment, fix, sensitivity, spring_constant)")
    options = {"sensitivity": sensitivity, "spring_constant": spring_constant,
               "fit": fit_options}
    if not paths:
        return []
    # Bad options raise here, as fit() would, before any task is sent.
    _core.afm_check_fit(str(fit_options.get("model", "hertz")),
                        str(fit_options.get("tip", "parabolic:radius=1e-5")),
                        float(fit_options.get("poisson_ratio", 0.5)),
                        str(fit_options.get("segment", "approach")), _fixed(fit_options.get("fix")))
    own = executor is None
    if own:
        executor = ThreadPoolExecutor(_core.available_cpus(), thread_name_prefix="mdrsim-fit")
    try:
        futures = [executor.submit(_fit_file, p, options) for p in paths]
        documents = []
        started = last = time.perf_counter()
        for done, future in enumerate(futures, start=1):
            documents.extend(future.result())
            now = time.perf_counter()
            if now - last >= _PROGRESS_SECONDS and done < len(futures):
                last = now
                _log.info("fit: %d of %d files in %.0f s", done, len(futures), now - started)
        return documents
    finally:
        if own:
            executor.shutdown()
